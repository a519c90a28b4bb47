#!/usr/bin/env python3
"""Renders one frame of a glTF 2.0 file (.gltf or .glb) with three.js in headless Chromium
and writes it as a PNG: the reference image Velocity's glTF pipeline is compared with.

    render.py MODEL --out OUT.png [--size WxH] [--camera EYE,TARGET[,UP] --yfov DEG
              --znear N --zfar N] [--light SPEC]... [--ambient R,G,B] [--file-lights]
              [--tone none|aces|neutral] [--exposure E] [--bg R,G,B] [--antialias]
              [--shadows [--shadow-map N] [--shadow-bias B] [--shadow-normal-bias B]]

Conventions (the same as Velocity's):
  camera   OpenGL's: the camera looks down its -Z axis with +Y up, placed by look_at(eye,
           target, up); perspective with a vertical field of view in degrees. Without
           --camera the model is framed (with --yfov): looking down -Z at its bounding
           sphere; the camera used is printed.
  lights   KHR_lights_punctual's units, which three.js uses as they are: directional in
           lux, point and spot in candela with inverse-square falloff; colours linear.
             directional:DX,DY,DZ:R,G,B:INTENSITY          shining along D
             point:X,Y,Z:R,G,B:INTENSITY[:RANGE]          RANGE 0 or none: unbounded
             spot:X,Y,Z:DX,DY,DZ:R,G,B:INTENSITY:INNER:OUTER[:RANGE]
                                                           cone half-angles in degrees
           A Lambertian surface of base colour c facing a directional light of intensity E
           sends c/pi * E (three.js's BRDF_Lambert, no factor of pi in the light), so
           intensity pi shows white as 1.0. --ambient adds a uniform irradiance (linear).
           --shadows: each --light casts through an N x N PCF shadow map fitted to the
           model's bounding sphere (three.js's; its bias and normal bias as given).
           The file's own lights are removed unless --file-lights; there is never an
           environment map.
  colour   the file's materials as three.js's GLTFLoader makes them; output sRGB-encoded;
           --tone none (default, colours clamped) | aces | neutral (Khronos PBR Neutral),
           after multiplying by --exposure. --bg is the background as it appears in the
           output: sRGB values / 255.
  pixels   read back with gl.readPixels from the canvas's RGBA8 framebuffer, before any
           browser colour management; written top row first. One sample per pixel
           unless --antialias (the canvas's MSAA).

Exit status: 0 written; 1 any failure (one line on stderr: the model did not load, WebGL
is unavailable, a timeout, ...); 77 Chromium is not installed (ctest's skip code).
"""
from __future__ import annotations

import argparse
import base64
import json
import os
import pathlib
import sys
import time
from dataclasses import dataclass

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import chromium  # noqa: E402
import png  # noqa: E402
import three_install  # noqa: E402

PAGE = pathlib.Path(__file__).resolve().with_name("oracle.html").as_uri()
EXIT_NO_CHROMIUM = 77


@dataclass
class Image:
    width: int
    height: int
    rgb: bytes      # width * height * 3 bytes, top row first
    camera: dict    # the camera used (the framed one when none was given)
    info: str       # three.js revision and WebGL renderer
    warnings: list  # what three.js warned about while loading and drawing (ignored extensions, ...)

    def pixel(self, x: int, y: int) -> tuple[int, int, int]:
        i = 3 * (y * self.width + x)
        return tuple(self.rgb[i:i + 3])

    def save(self, path: str) -> None:
        png.write(path, self.width, self.height, 3, self.rgb)


def make_spec(model: str, width: int, height: int, camera: dict | None = None, lights: list | None = None,
              ambient=None, file_lights=False, tone="none", exposure=1.0, background=(0, 0, 0),
              antialias=False, shadows=None, frame_yfov=45.0) -> dict:
    """The request oracle.js's renderOracle takes (see there); model is a file path;
    shadows None or {"mapSize": N, "bias": B, "normalBias": B}; frame_yfov the field of view
    of the camera that frames the model when camera is None."""
    path = pathlib.Path(model).resolve()
    if not path.is_file():
        raise chromium.PageError("no such file")
    return {"model": path.as_uri(), "width": width, "height": height, "camera": camera, "frameYfov": frame_yfov,
            "lights": lights or [], "ambient": list(ambient) if ambient else None, "fileLights": file_lights,
            "tone": tone, "exposure": exposure, "background": list(background), "antialias": antialias,
            "shadows": shadows}


class Oracle:
    """A browser with the oracle page open, for one render or many (a test renders several
    models in one session: Chromium's start is most of the cost of a small frame).

        with Oracle(timeout=60) as oracle:
            image = oracle.render(make_spec("box.gltf", 320, 240))

    Raises chromium.ChromiumMissing, three_install.InstallError or chromium.PageError.
    """

    def __init__(self, timeout: float = 60):
        self.timeout = timeout

    def __enter__(self) -> "Oracle":
        path = chromium.find_chromium()  # first: without Chromium, nothing to install
        three_install.ensure_three()
        self._browser = chromium.Browser(time.monotonic() + self.timeout, path).__enter__()
        try:
            self._browser.open(PAGE)
            if not self._browser.evaluate("typeof window.renderOracle === 'function'"):
                errors = self._browser.take_messages()
                raise chromium.PageError(f"the oracle page did not start: {errors[0] if errors else 'no message'}")
        except BaseException:
            self._browser.__exit__(None, None, None)
            raise
        return self

    def __exit__(self, *exc) -> None:
        self._browser.__exit__(*exc)

    def render(self, spec: dict, timeout: float | None = None) -> Image:
        """One frame; timeout (default: the Oracle's) bounds this render alone."""
        self._browser.deadline = time.monotonic() + (self.timeout if timeout is None else timeout)
        self._browser.take_messages()  # forget the previous render's
        r = self._browser.evaluate(f"window.renderOracle({json.dumps(spec)})")
        warnings = self._browser.take_messages(("error", "warning"))
        rgba = base64.b64decode(r["rgba"])
        rgb = bytearray(len(rgba) // 4 * 3)  # the canvas is opaque: alpha is 255, dropped
        rgb[0::3], rgb[1::3], rgb[2::3] = rgba[0::4], rgba[1::4], rgba[2::4]
        return Image(r["width"], r["height"], bytes(rgb), r["camera"], f"three r{r['three']} on {r['renderer']}",
                     warnings)


# --- the command line
def _floats(text: str, counts: tuple[int, ...], what: str) -> list[float]:
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) not in counts:
        raise argparse.ArgumentTypeError(f"{what}: expected {' or '.join(str(c) for c in counts)} "
                                         f"comma-separated numbers, got '{text}'")
    return values


def _size(text: str) -> tuple[int, int]:
    w, _, h = text.partition("x")
    if not (w.isdigit() and h.isdigit() and 1 <= int(w) <= 8192 and 1 <= int(h) <= 8192):
        raise argparse.ArgumentTypeError(f"--size: expected WxH with each 1..8192, got '{text}'")
    return int(w), int(h)


def _light(text: str) -> dict:
    kind, *f = text.split(":")
    try:
        if kind == "directional" and len(f) == 3:
            return {"type": kind, "direction": _floats(f[0], (3,), "direction"), "color": _floats(f[1], (3,), "colour"),
                    "intensity": float(f[2])}
        if kind == "point" and len(f) in (3, 4):
            return {"type": kind, "position": _floats(f[0], (3,), "position"), "color": _floats(f[1], (3,), "colour"),
                    "intensity": float(f[2]), "range": float(f[3]) if len(f) == 4 else 0.0}
        if kind == "spot" and len(f) in (6, 7):
            return {"type": kind, "position": _floats(f[0], (3,), "position"),
                    "direction": _floats(f[1], (3,), "direction"), "color": _floats(f[2], (3,), "colour"),
                    "intensity": float(f[3]), "inner": float(f[4]), "outer": float(f[5]),
                    "range": float(f[6]) if len(f) == 7 else 0.0}
    except ValueError:
        pass
    raise argparse.ArgumentTypeError(f"--light: expected directional:D:RGB:I, point:P:RGB:I[:RANGE] or "
                                     f"spot:P:D:RGB:I:INNER:OUTER[:RANGE], got '{text}'")


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 2)[2])
    p.add_argument("model", help=".gltf or .glb file")
    p.add_argument("--out", required=True, help="PNG to write")
    p.add_argument("--size", type=_size, default=(640, 480), help="image size WxH (default 640x480)")
    p.add_argument("--camera", type=lambda t: _floats(t, (6, 9), "--camera"), help="eye,target[,up] (up 0,1,0)")
    p.add_argument("--yfov", type=float, default=45.0, help="vertical field of view, degrees (default 45)")
    p.add_argument("--znear", type=float, default=0.05, help="near plane with --camera (default 0.05)")
    p.add_argument("--zfar", type=float, default=1000.0, help="far plane with --camera (default 1000)")
    p.add_argument("--light", type=_light, action="append", default=[], help="a punctual light (repeatable)")
    p.add_argument("--ambient", type=lambda t: _floats(t, (3,), "--ambient"), help="ambient irradiance r,g,b (linear)")
    p.add_argument("--file-lights", action="store_true", help="keep the file's KHR_lights_punctual lights")
    p.add_argument("--tone", choices=("none", "aces", "neutral"), default="none", help="tone mapping (default none)")
    p.add_argument("--exposure", type=float, default=1.0, help="multiplies the colour before tone mapping")
    p.add_argument("--bg", type=lambda t: _floats(t, (3,), "--bg"), default=[0, 0, 0],
                   help="background r,g,b: output sRGB / 255 (default 0,0,0)")
    p.add_argument("--antialias", action="store_true", help="MSAA on the canvas")
    p.add_argument("--shadows", action="store_true", help="shadow maps for the --light lights")
    p.add_argument("--shadow-map", type=int, default=2048, help="shadow map size (default 2048)")
    p.add_argument("--shadow-bias", type=float, default=-0.0005,
                   help="depth bias, in the shadow map's [0, 1] depth (default -0.0005)")
    p.add_argument("--shadow-normal-bias", type=float, default=0.0,
                   help="offset along the normal, in world units (default 0)")
    p.add_argument("--timeout", type=float, default=60.0,
                   help="seconds for Chromium's start and the render (default 60; npm ci, when needed, has 300 more)")
    return p.parse_args(argv)


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    camera = None
    if args.camera:
        c = args.camera + ([0, 1, 0] if len(args.camera) == 6 else [])
        camera = {"eye": c[0:3], "target": c[3:6], "up": c[6:9], "yfov": args.yfov, "znear": args.znear,
                  "zfar": args.zfar}
    started = time.monotonic()
    try:
        spec = make_spec(args.model, *args.size, camera=camera, lights=args.light, ambient=args.ambient,
                         file_lights=args.file_lights, tone=args.tone, exposure=args.exposure,
                         background=args.bg, antialias=args.antialias, frame_yfov=args.yfov,
                         shadows={"mapSize": args.shadow_map, "bias": args.shadow_bias,
                                  "normalBias": args.shadow_normal_bias} if args.shadows else None)
        with Oracle(timeout=args.timeout) as oracle:  # --timeout bounds the start and the render together
            image = oracle.render(spec, timeout=args.timeout - (time.monotonic() - started))
        image.save(args.out)
    except chromium.ChromiumMissing as e:
        print(f"render.py: {e}", file=sys.stderr)
        return EXIT_NO_CHROMIUM
    except chromium.Timeout as e:
        print(f"render.py: {args.model}: timed out after {args.timeout:g} s ({e})", file=sys.stderr)
        return 1
    except (chromium.PageError, three_install.InstallError, OSError) as e:
        print(f"render.py: {args.model}: {e}", file=sys.stderr)
        return 1
    cam = image.camera
    print(f"wrote {args.out} {image.width}x{image.height} in {time.monotonic() - started:.1f} s, {image.info}; "
          f"camera eye={','.join(f'{v:g}' for v in cam['eye'])} target={','.join(f'{v:g}' for v in cam['target'])} "
          f"yfov={cam['yfov']:g} znear={cam['znear']:g} zfar={cam['zfar']:g}")
    for w in image.warnings:
        print(f"render.py: {args.model}: three.js: {w}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
