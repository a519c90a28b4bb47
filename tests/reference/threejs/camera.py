"""The pinhole camera render.py gives three.js, in plain Python for the checks: OpenGL's
look_at (looking down -Z, +Y up) and a vertical field of view; pixel (i, j) has its centre
at (i + 0.5, j + 0.5), row 0 at the top."""
from __future__ import annotations

import math
from dataclasses import dataclass


def _sub(a, b): return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
def _dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def _cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def normalize(a): n = math.sqrt(_dot(a, a)); return [a[0] / n, a[1] / n, a[2] / n]


@dataclass
class Camera:
    eye: list
    target: list
    up: list
    yfov: float   # degrees
    width: int
    height: int

    def _basis(self):
        f = normalize(_sub(self.target, self.eye))
        s = normalize(_cross(f, self.up))
        return f, s, _cross(s, f)

    def _half_extent(self):
        t = math.tan(math.radians(self.yfov) / 2)
        return t * self.width / self.height, t

    def project(self, p) -> tuple[float, float]:
        """Where world point p lands in the image, in pixels (x right, y down)."""
        f, s, u = self._basis()
        d = _sub(p, self.eye)
        depth = _dot(d, f)
        hx, hy = self._half_extent()
        return ((_dot(d, s) / (depth * hx) + 1) / 2 * self.width, (1 - _dot(d, u) / (depth * hy)) / 2 * self.height)

    def on_plane_z0(self, i: int, j: int) -> list:
        """The point of the plane z = 0 seen through pixel (i, j)'s centre."""
        f, s, u = self._basis()
        hx, hy = self._half_extent()
        nx, ny = (i + 0.5) / self.width * 2 - 1, 1 - (j + 0.5) / self.height * 2
        ray = [f[k] + s[k] * nx * hx + u[k] * ny * hy for k in range(3)]
        t = -self.eye[2] / ray[2]
        return [self.eye[k] + t * ray[k] for k in range(3)]

    def args(self) -> list[str]:
        """render.py's options for this camera."""
        return ["--size", f"{self.width}x{self.height}", "--camera", ",".join(f"{v:g}" for v in self.eye + self.target + self.up),
                "--yfov", f"{self.yfov:g}"]


def srgb_encode(linear: float) -> float:
    """The sRGB transfer function (IEC 61966-2-1), on [0, 1]: what three.js writes."""
    linear = min(max(linear, 0.0), 1.0)
    return 12.92 * linear if linear <= 0.0031308 else 1.055 * linear ** (1 / 2.4) - 0.055
