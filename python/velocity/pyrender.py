"""pyrender 0.1.45's public API on Velocity: `import velocity.pyrender as pyrender` and a
pyrender script renders on the CPU, with no OpenGL, EGL or display.

The scene graph, meshes, materials, cameras and lights are pyrender's own model (plain
Python objects with pyrender's names, defaults and behaviour); OffscreenRenderer.render
turns the scene into a `velocity` scene (meshes converted once and cached) and renders it
with the engine. Where the results differ from pyrender's, and why: docs/python.md.
"""
from __future__ import annotations

import copy
import enum
import math
from typing import Any, Iterable

import numpy as np

from . import _velocity as _v

__all__ = [
    "DirectionalLight", "GLTF", "IntrinsicsCamera", "Light", "Material", "Mesh", "MetallicRoughnessMaterial",
    "Node", "OffscreenRenderer", "OrthographicCamera", "PerspectiveCamera", "PointLight", "Primitive",
    "RenderFlags", "Sampler", "Scene", "SpecularGlossinessMaterial", "SpotLight", "Texture", "Camera", "Viewer",
]

DEFAULT_Z_NEAR = 0.05
DEFAULT_Z_FAR = 100.0


class RenderFlags(enum.IntFlag):
    """pyrender's RenderFlags, every member with its value. Combine with `|`."""

    NONE = 0
    DEPTH_ONLY = 1
    OFFSCREEN = 2
    FLIP_WIREFRAME = 4
    ALL_WIREFRAME = 8
    ALL_SOLID = 16
    SHADOWS_DIRECTIONAL = 32
    SHADOWS_POINT = 64
    SHADOWS_SPOT = 128
    SHADOWS_ALL = 32 | 64 | 128
    VERTEX_NORMALS = 256
    FACE_NORMALS = 512
    SKIP_CULL_FACES = 1024
    RGBA = 2048
    FLAT = 4096
    SEG = 8192


# Flags Velocity cannot honour, and why (render() raises naming them).
_REFUSED = {
    RenderFlags.VERTEX_NORMALS: "Velocity does not draw normal vectors as lines",
    RenderFlags.FACE_NORMALS: "Velocity does not draw normal vectors as lines",
}


_REFUSED_MASK = int(RenderFlags.VERTEX_NORMALS | RenderFlags.FACE_NORMALS)
_SEG, _FLAT, _DEPTH_ONLY = int(RenderFlags.SEG), int(RenderFlags.FLAT), int(RenderFlags.DEPTH_ONLY)
_FLIP_WIREFRAME, _ALL_SOLID, _SHADOWS = (int(RenderFlags.FLIP_WIREFRAME), int(RenderFlags.ALL_SOLID),
                                         int(RenderFlags.SHADOWS_ALL))
# What the engine's render takes as it is (velocity's RenderFlags use pyrender's values).
_NATIVE = int(RenderFlags.DEPTH_ONLY | RenderFlags.ALL_WIREFRAME | RenderFlags.SKIP_CULL_FACES | RenderFlags.RGBA |
              RenderFlags.SHADOWS_ALL)


class GLTF:
    """pyrender's GLTF constants (OpenGL enum values): filters, wraps, primitive modes."""

    NEAREST = 9728
    LINEAR = 9729
    NEAREST_MIPMAP_NEAREST = 9984
    LINEAR_MIPMAP_NEAREST = 9985
    NEAREST_MIPMAP_LINEAR = 9986
    LINEAR_MIPMAP_LINEAR = 9987
    CLAMP_TO_EDGE = 33071
    MIRRORED_REPEAT = 33648
    REPEAT = 10497
    POINTS = 0
    LINES = 1
    LINE_LOOP = 2
    LINE_STRIP = 3
    TRIANGLES = 4
    TRIANGLE_STRIP = 5
    TRIANGLE_FAN = 6


def _vec(value: Any, n: int, default: Iterable[float], what: str) -> np.ndarray:
    """A colour or vector of n floats; pyrender's colours may also be 0..255 integers."""
    if value is None:
        return np.array(list(default), dtype=np.float64)
    a = np.asarray(value)
    if a.dtype.kind not in "uif":
        raise TypeError(f"{what}: expected numbers, got {a.dtype}")
    if a.ndim != 1 or a.shape[0] not in (3, 4) or a.shape[0] > n:
        raise ValueError(f"{what}: expected {n} numbers, got shape {a.shape}")
    a = a.astype(np.float64)
    if a.dtype.kind in "ui" or (np.asarray(value).dtype.kind in "ui" and a.max(initial=0) > 1):
        a = a / 255.0
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{what}: entries must be finite")
    if a.shape[0] < n:
        a = np.concatenate([a, np.ones(n - a.shape[0])])
    return a


def _matrix(value: Any, what: str = "pose") -> np.ndarray:
    if value is None:
        return np.eye(4)
    a = np.asarray(value, dtype=np.float64)
    if a.shape != (4, 4):
        raise ValueError(f"{what}: expected a 4x4 matrix, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{what}: entries must be finite")
    return a.copy()


# ---------------------------------------------------------------- textures, materials
class Sampler:
    """How a texture is sampled: pyrender's Sampler (GLTF filter and wrap values)."""

    def __init__(self, name=None, magFilter=None, minFilter=None, wrapS=GLTF.REPEAT, wrapT=GLTF.REPEAT):
        self.name, self.magFilter, self.minFilter, self.wrapS, self.wrapT = name, magFilter, minFilter, wrapS, wrapT

    def _filter(self) -> str:
        if self.magFilter == GLTF.NEAREST and self.minFilter in (None, GLTF.NEAREST, GLTF.NEAREST_MIPMAP_NEAREST):
            return "nearest"
        if self.minFilter in (GLTF.LINEAR, GLTF.NEAREST):
            return "bilinear"
        return "trilinear"  # pyrender's default: mip-mapped, linear

    def _wrap(self) -> str:
        return {GLTF.CLAMP_TO_EDGE: "clamp", GLTF.MIRRORED_REPEAT: "mirror"}.get(self.wrapS, "repeat")


def _image_array(source: Any) -> np.ndarray:
    """A texture source (numpy array or PIL image) as an H x W x C uint8 array."""
    if hasattr(source, "mode") and hasattr(source, "size") and not isinstance(source, np.ndarray):  # PIL
        if source.mode not in ("L", "LA", "RGB", "RGBA"):
            source = source.convert("RGBA")
        source = np.asarray(source)
    a = np.asarray(source)
    if a.dtype.kind == "f":
        if not np.all(np.isfinite(a)):
            raise ValueError("texture: pixel values must be finite")
        a = np.clip(np.rint(a * 255.0), 0, 255).astype(np.uint8)
    elif a.dtype.kind in "ui":
        a = a.astype(np.uint8)
    else:
        raise TypeError(f"texture: expected an image of numbers, got {a.dtype}")
    if a.ndim == 2:
        a = a[:, :, None]
    if a.ndim != 3 or not 1 <= a.shape[2] <= 4:
        raise ValueError(f"texture: expected an H x W x C image (C 1..4), got shape {a.shape}")
    return a


class Texture:
    """pyrender's Texture: an image (numpy array or PIL image) and its Sampler."""

    def __init__(self, name=None, sampler=None, source=None, source_channels=None, width=None, height=None,
                 tex_type=None, data_format=None):
        self.name = name
        self.sampler = sampler if sampler is not None else Sampler()
        self.source_channels = source_channels
        self.source = source
        self.width, self.height = width, height
        self.tex_type, self.data_format = tex_type, data_format

    @property
    def source(self):
        return self._source

    @source.setter
    def source(self, value):
        self._source = None if value is None else _image_array(value)
        if self._source is not None and self.source_channels is None:
            self.source_channels = {1: "R", 2: "RG", 3: "RGB", 4: "RGBA"}[self._source.shape[2]]

    def is_transparent(self, cutoff=1.0):
        s = self._source
        return s is not None and s.shape[2] == 4 and bool(np.any(s[:, :, 3] < cutoff * 255))

    def delete(self):
        pass


def _texture(value: Any) -> "Texture | None":
    if value is None or isinstance(value, Texture):
        return value
    return Texture(source=value)


class Material:
    """pyrender's Material base: the glTF 2.0 properties shared by every material."""

    def __init__(self, name=None, normalTexture=None, occlusionTexture=None, emissiveTexture=None,
                 emissiveFactor=None, alphaMode=None, alphaCutoff=None, doubleSided=False, smooth=True,
                 wireframe=False):
        self.name = name
        self.normalTexture = _texture(normalTexture)
        self.occlusionTexture = _texture(occlusionTexture)
        self.emissiveTexture = _texture(emissiveTexture)
        self.emissiveFactor = _vec(emissiveFactor, 3, (0, 0, 0), "emissiveFactor")
        self.alphaMode = alphaMode if alphaMode is not None else "OPAQUE"
        if self.alphaMode not in ("OPAQUE", "MASK", "BLEND"):
            raise ValueError(f"alphaMode: expected OPAQUE, MASK or BLEND, got {alphaMode!r}")
        self.alphaCutoff = 0.5 if alphaCutoff is None else float(alphaCutoff)
        self.doubleSided, self.smooth, self.wireframe = bool(doubleSided), bool(smooth), bool(wireframe)

    # Velocity's own: the factors the engine's Material takes (subclasses fill them in).
    def _base(self):
        return np.ones(4), None, None, None

    @property
    def is_transparent(self) -> bool:
        base, texture, _, _ = self._base()
        return self.alphaMode == "BLEND" and (base[3] < 1 or (texture is not None and texture.is_transparent()))

    def _native(self, wireframe: bool, unlit: bool = False) -> "_v.Material":
        base, texture, metallic, roughness = self._base()
        # BLEND with nothing transparent draws as opaque, as pyrender sorts only what is.
        mode = self.alphaMode if self.alphaMode != "BLEND" or self.is_transparent else "OPAQUE"
        kwargs = dict(color=np.clip(base[:3], 0, 1), alpha=float(np.clip(base[3], 0, 1)), alpha_mode=mode,
                      alpha_cutoff=float(np.clip(self.alphaCutoff, 0, 1)), two_sided=self.doubleSided,
                      emissive=np.clip(self.emissiveFactor, 0, None),
                      # pyrender's factors and vertex colours are linear light, but its FLAT
                      # (unlit) shader writes them as they are: display values.
                      color_space="srgb" if unlit else "linear")
        if texture is not None and texture.source is not None:
            kwargs.update(image=texture.source, wrap=texture.sampler._wrap(), filter=texture.sampler._filter())
        if wireframe:
            kwargs["shading"] = "wire"
        elif unlit:
            kwargs["shading"] = "unlit"
        else:
            kwargs.update(metallic=float(np.clip(metallic, 0, 1)), roughness=float(np.clip(roughness, 0, 1)))
        return _v.Material(**kwargs)


class MetallicRoughnessMaterial(Material):
    """pyrender's MetallicRoughnessMaterial (glTF 2.0's metallic-roughness model)."""

    def __init__(self, name=None, normalTexture=None, occlusionTexture=None, emissiveTexture=None,
                 emissiveFactor=None, alphaMode=None, alphaCutoff=None, doubleSided=False, smooth=True,
                 wireframe=False, baseColorFactor=None, baseColorTexture=None, metallicFactor=1.0,
                 roughnessFactor=1.0, metallicRoughnessTexture=None):
        super().__init__(name, normalTexture, occlusionTexture, emissiveTexture, emissiveFactor, alphaMode,
                         alphaCutoff, doubleSided, smooth, wireframe)
        self.baseColorFactor = _vec(baseColorFactor, 4, (1, 1, 1, 1), "baseColorFactor")
        self.baseColorTexture = _texture(baseColorTexture)
        self.metallicFactor = float(metallicFactor) if metallicFactor is not None else 1.0
        self.roughnessFactor = float(roughnessFactor) if roughnessFactor is not None else 1.0
        self.metallicRoughnessTexture = _texture(metallicRoughnessTexture)

    def _base(self):
        return self.baseColorFactor, self.baseColorTexture, self.metallicFactor, self.roughnessFactor


class SpecularGlossinessMaterial(Material):
    """pyrender's SpecularGlossinessMaterial, drawn as metallic-roughness (metallic 0,
    roughness 1 - glossiness): the engine has no specular-glossiness model."""

    def __init__(self, name=None, normalTexture=None, occlusionTexture=None, emissiveTexture=None,
                 emissiveFactor=None, alphaMode=None, alphaCutoff=None, doubleSided=False, smooth=True,
                 wireframe=False, diffuseFactor=None, diffuseTexture=None, specularFactor=None,
                 glossinessFactor=1.0, specularGlossinessTexture=None):
        super().__init__(name, normalTexture, occlusionTexture, emissiveTexture, emissiveFactor, alphaMode,
                         alphaCutoff, doubleSided, smooth, wireframe)
        self.diffuseFactor = _vec(diffuseFactor, 4, (1, 1, 1, 1), "diffuseFactor")
        self.diffuseTexture = _texture(diffuseTexture)
        self.specularFactor = _vec(specularFactor, 3, (1, 1, 1), "specularFactor")
        self.glossinessFactor = float(glossinessFactor)
        self.specularGlossinessTexture = _texture(specularGlossinessTexture)

    def _base(self):
        return self.diffuseFactor, self.diffuseTexture, 0.0, 1.0 - self.glossinessFactor


# ---------------------------------------------------------------- primitives, meshes
def _array(value: Any, cols: "tuple[int, ...]", what: str, kinds: str = "f", dtype=np.float32):
    if value is None:
        return None
    a = np.asarray(value)
    if a.dtype.kind not in kinds + ("ui" if "f" in kinds else ""):
        raise TypeError(f"{what}: expected {'floats' if 'f' in kinds else 'integers'}, got {a.dtype}")
    if a.ndim != 2 or a.shape[1] not in cols:
        raise ValueError(f"{what}: expected an N x {'/'.join(map(str, cols))} array, got shape {a.shape}")
    return a.astype(dtype, copy=False) if dtype is not None else a


class Primitive:
    """pyrender's Primitive: one draw of one material (glTF's mesh primitive)."""

    def __init__(self, positions, normals=None, tangents=None, texcoord_0=None, texcoord_1=None, color_0=None,
                 joints_0=None, weights_0=None, indices=None, material=None, mode=None, targets=None,
                 poses=None):
        self.mode = GLTF.TRIANGLES if mode is None else int(mode)
        if self.mode not in (GLTF.POINTS, GLTF.TRIANGLES, GLTF.TRIANGLE_STRIP, GLTF.TRIANGLE_FAN):
            raise ValueError(f"Primitive: mode {self.mode} (lines) is not drawn by Velocity; "
                             "use POINTS, TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN")
        self.positions = _array(positions, (3,), "positions")
        self.normals = _array(normals, (3,), "normals")
        self.tangents = _array(tangents, (4,), "tangents")
        self.texcoord_0 = _array(texcoord_0, (2,), "texcoord_0")
        self.texcoord_1 = _array(texcoord_1, (2,), "texcoord_1")
        self.color_0 = None if color_0 is None else _colors(color_0, "color_0")
        self.joints_0, self.weights_0, self.targets = joints_0, weights_0, targets
        self.indices = None if indices is None else _array(indices, (1, 2, 3), "indices", "ui", np.int64)
        if self.indices is not None and self.indices.shape[1] != 3 and self.mode != GLTF.POINTS:
            raise ValueError(f"indices: expected an N x 3 array, got shape {self.indices.shape}")
        n = len(self.positions)
        for what in ("normals", "tangents", "texcoord_0", "texcoord_1", "color_0"):
            a = getattr(self, what)
            if a is not None and len(a) != n:
                raise ValueError(f"{what}: expected {n} rows (one per position), got {len(a)}")
        self.material = material if material is not None else MetallicRoughnessMaterial()
        self.poses = poses
        self._cache: dict = {}

    @property
    def poses(self):
        return self._poses

    @poses.setter
    def poses(self, value):
        if value is None:
            self._poses = None
            return
        p = np.asarray(value, dtype=np.float64)
        if p.ndim == 2:
            p = p[None]
        if p.ndim != 3 or p.shape[1:] != (4, 4):
            raise ValueError(f"poses: expected N x 4 x 4 matrices, got shape {p.shape}")
        if not np.all(np.isfinite(p)):
            raise ValueError("poses: entries must be finite")
        self._poses = p

    @property
    def bounds(self) -> np.ndarray:
        pts = self.positions
        if self._poses is not None:
            lo, hi = pts.min(axis=0), pts.max(axis=0)
            corners = np.array([[x, y, z, 1.0] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
            pts = np.concatenate([(corners @ p.T)[:, :3] for p in self._poses])
        return np.array([pts.min(axis=0), pts.max(axis=0)])

    @property
    def centroid(self):
        return np.mean(self.bounds, axis=0)

    @property
    def extents(self):
        return np.diff(self.bounds, axis=0).reshape(-1)

    @property
    def scale(self):
        return float(np.linalg.norm(self.extents))

    @property
    def is_transparent(self):
        return self.material.is_transparent or (self.color_0 is not None and self.color_0.shape[1] == 4 and
                                                bool(np.any(self.color_0[:, 3] < 1)))

    def _faces(self) -> np.ndarray:
        n = len(self.positions)
        idx = self.indices.reshape(-1) if self.indices is not None else np.arange(n)
        if self.mode == GLTF.TRIANGLES:
            if len(idx) % 3:
                raise ValueError("indices: a TRIANGLES primitive needs a multiple of 3 indices")
            faces = idx.reshape(-1, 3)
        elif self.mode == GLTF.TRIANGLE_STRIP:
            k = np.arange(max(len(idx) - 2, 0))
            even = k % 2 == 0
            faces = np.stack([idx[k], np.where(even, idx[k + 1], idx[k + 2]), np.where(even, idx[k + 2], idx[k + 1])], 1)
        else:  # TRIANGLE_FAN
            k = np.arange(1, max(len(idx) - 1, 1))
            faces = np.stack([np.full(len(k), idx[0] if len(idx) else 0), idx[k], idx[k + 1]], 1)
        if faces.size and (faces.min() < 0 or faces.max() >= n):
            raise ValueError(f"indices: every index must be in 0..{n - 1}")
        return faces

    def _native(self, wireframe: bool, unlit: bool) -> "_v.Mesh":
        """The engine's mesh for this primitive (cached: pyrender's meshes do not change
        once on the GPU either; set an attribute to a new array and it is remade)."""
        key = (wireframe, unlit, id(self.positions), id(self.normals), id(self.texcoord_0), id(self.color_0),
               id(self.indices), id(self.material))
        mesh = self._cache.get(key)
        if mesh is None:
            material = self.material._native(wireframe, unlit)
            base = self.material._base()[0]
            colors = None
            if self.color_0 is not None:  # pyrender multiplies the base colour by them
                colors = np.clip(self.color_0[:, :3] * base[:3], 0, 1).astype(np.float32)
            uvs = None
            if self.texcoord_0 is not None:  # pyrender's v runs up from the image's bottom row; Velocity's down
                uvs = np.column_stack([self.texcoord_0[:, 0], 1.0 - self.texcoord_0[:, 1]]).astype(np.float32)
            mesh = _v.Mesh.from_arrays(self.positions, self._faces(), normals=self.normals, uvs=uvs,
                                       colors=colors, material=material, name=self.material.name or "primitive")
            if len(self._cache) > 8:
                self._cache.clear()
            self._cache[key] = mesh
        return mesh


def _colors(value: Any, what: str) -> np.ndarray:
    a = np.asarray(value)
    if a.ndim == 1 and a.shape[0] in (3, 4):
        a = a[None]
    if a.dtype.kind not in "uif" or a.ndim != 2 or a.shape[1] not in (3, 4):
        raise ValueError(f"{what}: expected N x 3 or N x 4 colours, got shape {a.shape} ({a.dtype})")
    return a.astype(np.float32) / 255.0 if a.dtype.kind in "ui" else a.astype(np.float32)


class Mesh:
    """pyrender's Mesh: primitives drawn together under one node."""

    def __init__(self, primitives, name=None, weights=None, is_visible=True):
        self.primitives = list(primitives)
        if not all(isinstance(p, Primitive) for p in self.primitives):
            raise TypeError("Mesh: primitives must be Primitive objects")
        self.name, self.weights, self.is_visible = name, weights, bool(is_visible)

    @property
    def bounds(self) -> np.ndarray:
        b = np.array([p.bounds for p in self.primitives])
        return np.array([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])

    @property
    def centroid(self):
        return np.mean(self.bounds, axis=0)

    @property
    def extents(self):
        return np.diff(self.bounds, axis=0).reshape(-1)

    @property
    def scale(self):
        return float(np.linalg.norm(self.extents))

    @property
    def is_transparent(self):
        return any(p.is_transparent for p in self.primitives)

    @staticmethod
    def from_points(points, colors=None, normals=None, is_visible=True, poses=None):
        """A point cloud: one point per row of `points` (N x 3), coloured by `colors`
        (N x 3/4 floats in [0, 1] or uint8, or one colour for all)."""
        points = _array(points, (3,), "points")
        if colors is not None:
            colors = _colors(colors, "colors")
            if len(colors) == 1:
                colors = np.repeat(colors, len(points), axis=0)
        return Mesh([Primitive(positions=points, normals=normals, color_0=colors, mode=GLTF.POINTS, poses=poses)],
                    is_visible=is_visible)

    @staticmethod
    def from_trimesh(mesh, material=None, is_visible=True, poses=None, wireframe=False, smooth=True):
        """A mesh from a trimesh.Trimesh, or a list of them (one primitive each): anything
        with trimesh's attributes (`vertices`, `faces`, `vertex_normals`, `face_normals`,
        `visual` with `kind` 'vertex', 'face' or 'texture', `vertex_colors`,
        `face_colors`, `uv`, `material`)."""
        meshes = list(mesh) if isinstance(mesh, (list, tuple, set, np.ndarray)) else [mesh]
        primitives = []
        for m in meshes:
            if not (hasattr(m, "vertices") and hasattr(m, "faces")):
                raise TypeError(f"Expected a Trimesh or a list, got a {type(m)}")
            vertices, faces = np.asarray(m.vertices), np.asarray(m.faces)
            if smooth:
                positions, indices = vertices, faces
                normals = np.asarray(m.vertex_normals) if hasattr(m, "vertex_normals") else None
            else:  # every face its own corners, with the face's normal
                positions, indices = vertices[faces].reshape(-1, 3), None
                normals = np.repeat(np.asarray(m.face_normals), 3, axis=0) if hasattr(m, "face_normals") else None
            color_0, texcoord_0, mat = _trimesh_visuals(m, faces, smooth, material)
            if material is not None:
                mat = copy.deepcopy(material)
            if mat is None:
                mat = MetallicRoughnessMaterial(alphaMode="BLEND", baseColorFactor=[0.3, 0.3, 0.3, 1.0],
                                                metallicFactor=0.2, roughnessFactor=0.8)
            mat.wireframe = wireframe
            primitives.append(Primitive(positions=positions, normals=normals, texcoord_0=texcoord_0,
                                        color_0=color_0, indices=indices, material=mat, mode=GLTF.TRIANGLES,
                                        poses=poses))
        return Mesh(primitives, is_visible=is_visible)


def _trimesh_visuals(m: Any, faces: np.ndarray, smooth: bool, material: Any):
    """(colours, uvs, material) from a trimesh's `visual`, as pyrender reads them."""
    visual = getattr(m, "visual", None)
    colors = uvs = None
    if visual is None or not getattr(visual, "defined", True):
        return colors, uvs, material
    kind = getattr(visual, "kind", None)
    white = dict(alphaMode="BLEND", baseColorFactor=[1.0, 1.0, 1.0, 1.0], metallicFactor=0.2, roughnessFactor=0.8)
    if material is None and kind == "vertex":
        vc = np.asarray(visual.vertex_colors)
        colors = vc if smooth else vc[faces].reshape(-1, vc.shape[1])
        material = MetallicRoughnessMaterial(**white)
    elif material is None and kind == "face":
        if smooth:
            raise ValueError("Cannot use face colors with a smooth mesh")
        colors = np.repeat(np.asarray(visual.face_colors), 3, axis=0)
        material = MetallicRoughnessMaterial(**white)
    if kind == "texture":
        uv = getattr(visual, "uv", None)
        if uv is not None and len(uv) != 0:
            uv = np.asarray(uv)
            uvs = uv if smooth else uv[faces].reshape(-1, uv.shape[1])
        if material is None:
            material = _trimesh_material(getattr(visual, "material", None))
    return colors, uvs, material


def _trimesh_material(mat: Any):
    """pyrender's reading of trimesh's PBRMaterial and SimpleMaterial (by their attributes)."""
    if mat is None or isinstance(mat, Material):
        return mat
    if hasattr(mat, "baseColorFactor") or hasattr(mat, "baseColorTexture"):  # trimesh's PBRMaterial
        g = lambda k: getattr(mat, k, None)  # noqa: E731
        return MetallicRoughnessMaterial(
            normalTexture=g("normalTexture"), occlusionTexture=g("occlusionTexture"),
            emissiveTexture=g("emissiveTexture"), emissiveFactor=g("emissiveFactor"), alphaMode="BLEND",
            baseColorFactor=g("baseColorFactor"), baseColorTexture=g("baseColorTexture"),
            metallicFactor=g("metallicFactor"), roughnessFactor=g("roughnessFactor"),
            metallicRoughnessTexture=g("metallicRoughnessTexture"), doubleSided=bool(g("doubleSided")),
            alphaCutoff=g("alphaCutoff"))
    # trimesh's SimpleMaterial: diffuse colour, image and the MTL's Ns as glossiness.
    glossiness = getattr(mat, "kwargs", {}).get("Ns", 1.0)
    if isinstance(glossiness, list):
        glossiness = float(glossiness[0])
    roughness = (2 / (float(glossiness) + 2)) ** (1.0 / 4.0)
    return MetallicRoughnessMaterial(alphaMode="BLEND", roughnessFactor=roughness,
                                     baseColorFactor=getattr(mat, "diffuse", None),
                                     baseColorTexture=getattr(mat, "image", None))


# ---------------------------------------------------------------- cameras, lights
class Camera:
    """pyrender's Camera base: znear and zfar along the view axis."""

    def __init__(self, znear=DEFAULT_Z_NEAR, zfar=DEFAULT_Z_FAR, name=None):
        self.name = name
        self.znear = znear
        self.zfar = zfar

    @property
    def znear(self):
        return self._znear

    @znear.setter
    def znear(self, value):
        value = float(value)
        if not (math.isfinite(value) and value >= 0):
            raise ValueError(f"znear: expected a finite value >= 0, got {value}")
        self._znear = value

    @property
    def zfar(self):
        return self._zfar

    @zfar.setter
    def zfar(self, value):
        if value is not None:
            value = float(value)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"zfar: expected a finite value > 0 (or None), got {value}")
        self._zfar = value

    _PARAMETERS = ("znear", "zfar", "yfov", "aspectRatio", "xmag", "ymag", "fx", "fy", "cx", "cy")

    def __setattr__(self, name, value):
        # Every setter checks what the constructor checks, and a bad value is not kept.
        if name not in self._PARAMETERS or not getattr(self, "_ready", False):
            return object.__setattr__(self, name, value)
        old = getattr(self, name)
        object.__setattr__(self, name, value)
        try:
            _check(self)
        except (ValueError, TypeError):
            object.__setattr__(self, name, old)
            raise

    def _near(self):
        # pyrender allows znear 0 for orthographic cameras; the engine needs a plane in front.
        return self.znear if self.znear > 0 else min(1e-3, (self.zfar or 1.0) * 1e-4)

    def get_projection_matrix(self, width=None, height=None):
        return self._native().get_projection_matrix(int(width), int(height))


def _check(camera):
    """The engine's checks of a camera's parameters, as ValueError."""
    try:
        camera._native()
    except _v.Error as e:
        raise ValueError(str(e)) from None
    except TypeError as e:
        raise TypeError(f"{type(camera).__name__}: {e}") from None
    camera._ready = True


class PerspectiveCamera(Camera):
    """pyrender's PerspectiveCamera: yfov (radians), aspectRatio (None: the image's)."""

    def __init__(self, yfov, znear=DEFAULT_Z_NEAR, zfar=None, aspectRatio=None, name=None):
        super().__init__(znear, zfar, name)
        self.yfov = yfov
        self.aspectRatio = aspectRatio
        _check(self)

    def _native(self):
        return _v.PerspectiveCamera(float(self.yfov), self._near(), self.zfar,
                                    None if self.aspectRatio is None else float(self.aspectRatio))


class OrthographicCamera(Camera):
    """pyrender's OrthographicCamera: xmag, ymag are half the view's width and height."""

    def __init__(self, xmag, ymag, znear=DEFAULT_Z_NEAR, zfar=DEFAULT_Z_FAR, name=None):
        super().__init__(znear, zfar, name)
        self.xmag, self.ymag = xmag, ymag
        _check(self)

    def _native(self):
        return _v.OrthographicCamera(float(self.xmag), float(self.ymag), self._near(),
                                     DEFAULT_Z_FAR if self.zfar is None else self.zfar)


class IntrinsicsCamera(Camera):
    """pyrender's IntrinsicsCamera: fx, fy, cx, cy in pixels (pyrender's convention)."""

    def __init__(self, fx, fy, cx, cy, znear=DEFAULT_Z_NEAR, zfar=DEFAULT_Z_FAR, name=None):
        super().__init__(znear, zfar, name)
        self.fx, self.fy, self.cx, self.cy = fx, fy, cx, cy
        _check(self)

    def _native(self):
        return _v.IntrinsicsCamera(float(self.fx), float(self.fy), float(self.cx), float(self.cy), self._near(),
                                   DEFAULT_Z_FAR if self.zfar is None else self.zfar)


class Light:
    """pyrender's Light base: colour (RGB in [0, 1]) times intensity (lux for a
    directional light, candela for point and spot lights). The engine's light takes
    intensity * pi: it divides by pi for its Lambertian model, and the PBR model gets
    the intensity itself, as pyrender's shader does."""

    def __init__(self, color=None, intensity=None, name=None):
        self.name = name
        self.color = color
        self.intensity = intensity

    @property
    def color(self):
        return self._color

    @color.setter
    def color(self, value):
        self._color = _vec(value, 3, (1, 1, 1), "color")[:3]

    @property
    def intensity(self):
        return self._intensity

    @intensity.setter
    def intensity(self, value):
        value = 1.0 if value is None else float(value)
        if not (math.isfinite(value) and value >= 0):
            raise ValueError(f"intensity: expected a finite value >= 0, got {value}")
        self._intensity = value

    @property
    def shadow_texture(self):
        return None


class DirectionalLight(Light):
    """pyrender's DirectionalLight: shines along the -Z axis of its node."""

    def _native(self):
        return _v.DirectionalLight(self.color, self.intensity * math.pi)


class PointLight(Light):
    """pyrender's PointLight: at its node's origin; range: glTF's cut-off (None: none)."""

    def __init__(self, color=None, intensity=None, range=None, name=None):
        super().__init__(color, intensity, name)
        self.range = range

    def _native(self):
        return _v.PointLight(self.color, self.intensity * math.pi, self.range)


class SpotLight(Light):
    """pyrender's SpotLight: shines along its node's -Z, full inside innerConeAngle,
    dark outside outerConeAngle (radians)."""

    def __init__(self, color=None, intensity=None, range=None, innerConeAngle=0.0, outerConeAngle=math.pi / 4.0,
                 name=None):
        super().__init__(color, intensity, name)
        self.range = range
        self.innerConeAngle, self.outerConeAngle = innerConeAngle, outerConeAngle
        self._native()  # validates

    def _native(self):
        return _v.SpotLight(self.color, self.intensity * math.pi, self.range, float(self.innerConeAngle),
                            float(self.outerConeAngle))


# ---------------------------------------------------------------- nodes, scenes
def _quaternion_matrix(q) -> np.ndarray:
    x, y, z, w = (float(v) for v in q)
    n = math.sqrt(x * x + y * y + z * z + w * w)
    if n == 0 or not math.isfinite(n):
        raise ValueError("rotation: expected a non-zero quaternion [x, y, z, w]")
    x, y, z, w = x / n, y / n, z / n, w / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def _matrix_quaternion(r: np.ndarray) -> np.ndarray:
    t = np.trace(r)
    if t > 0:
        s = math.sqrt(t + 1.0) * 2
        q = [(r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s, 0.25 * s]
    elif r[0, 0] > r[1, 1] and r[0, 0] > r[2, 2]:
        s = math.sqrt(1.0 + r[0, 0] - r[1, 1] - r[2, 2]) * 2
        q = [0.25 * s, (r[0, 1] + r[1, 0]) / s, (r[0, 2] + r[2, 0]) / s, (r[2, 1] - r[1, 2]) / s]
    elif r[1, 1] > r[2, 2]:
        s = math.sqrt(1.0 + r[1, 1] - r[0, 0] - r[2, 2]) * 2
        q = [(r[0, 1] + r[1, 0]) / s, 0.25 * s, (r[1, 2] + r[2, 1]) / s, (r[0, 2] - r[2, 0]) / s]
    else:
        s = math.sqrt(1.0 + r[2, 2] - r[0, 0] - r[1, 1]) * 2
        q = [(r[0, 2] + r[2, 0]) / s, (r[1, 2] + r[2, 1]) / s, 0.25 * s, (r[1, 0] - r[0, 1]) / s]
    return np.array(q)


class Node:
    """pyrender's Node: at most one mesh, camera or light, a pose relative to its parent
    (matrix, or translation / rotation quaternion [x, y, z, w] / scale) and children."""

    def __init__(self, name=None, camera=None, children=None, skin=None, matrix=None, mesh=None, rotation=None,
                 scale=None, translation=None, weights=None, light=None):
        self.name, self.camera, self.mesh, self.light = name, camera, mesh, light
        self.children = list(children) if children is not None else []
        self.skin, self.weights = skin, weights
        self._m = np.eye(4)
        if matrix is not None:
            self.matrix = matrix
        else:
            self._t = np.zeros(3) if translation is None else np.asarray(translation, dtype=np.float64).reshape(3)
            self._r = np.array([0.0, 0, 0, 1]) if rotation is None else np.asarray(rotation, dtype=np.float64).reshape(4)
            self._s = np.ones(3) if scale is None else np.asarray(scale, dtype=np.float64).reshape(3)
            self._compose()

    def _compose(self):
        m = np.eye(4)
        m[:3, :3] = _quaternion_matrix(self._r) * self._s
        m[:3, 3] = self._t
        if not np.all(np.isfinite(m)):
            raise ValueError("Node: translation, rotation and scale must be finite")
        self._m = m

    @property
    def matrix(self) -> np.ndarray:
        return self._m.copy()

    @matrix.setter
    def matrix(self, value):
        m = _matrix(value, "matrix")
        self._m = m
        self._t = m[:3, 3].copy()
        self._s = np.linalg.norm(m[:3, :3], axis=0)
        r = m[:3, :3] / np.where(self._s == 0, 1, self._s)
        self._r = _matrix_quaternion(r)

    @property
    def translation(self):
        return self._t.copy()

    @translation.setter
    def translation(self, value):
        self._t = np.asarray(value, dtype=np.float64).reshape(3)
        self._compose()

    @property
    def rotation(self):
        return self._r.copy()

    @rotation.setter
    def rotation(self, value):
        self._r = np.asarray(value, dtype=np.float64).reshape(4)
        self._compose()

    @property
    def scale(self):
        return self._s.copy()

    @scale.setter
    def scale(self, value):
        self._s = np.asarray(value, dtype=np.float64).reshape(3)
        self._compose()

    def __repr__(self):
        what = "mesh" if self.mesh is not None else "camera" if self.camera is not None else \
            "light" if self.light is not None else "empty"
        return f"<velocity.pyrender.Node {self.name!r} ({what})>"


class Scene:
    """pyrender's Scene: a tree of Nodes, a background colour and an ambient light."""

    def __init__(self, nodes=None, bg_color=None, ambient_light=None, name=None):
        self.name = name
        self.bg_color = bg_color
        self.ambient_light = ambient_light
        self.clear()
        for n in nodes or []:
            self.add_node(n)

    def clear(self):
        self._parent: dict = {}    # node -> parent node (None: a root)
        self._order: list = []     # nodes in the order they were added (parents first)
        self._main_camera_node = None

    @property
    def bg_color(self):
        return self._bg

    @bg_color.setter
    def bg_color(self, value):
        self._bg = _vec(value, 4, (1.0, 1.0, 1.0, 1.0), "bg_color")
        self._bg_native = tuple(float(v) for v in np.clip(self._bg, 0, 1))  # what each render gives the engine

    @property
    def ambient_light(self):
        return self._ambient

    @ambient_light.setter
    def ambient_light(self, value):
        self._ambient = _vec(value, 3, (0.0, 0.0, 0.0), "ambient_light")[:3]
        self._ambient_native = tuple(float(v) for v in np.clip(self._ambient, 0, None))

    # The node sets pyrender exposes.
    @property
    def nodes(self):
        return set(self._order)

    def _where(self, test):
        return {n for n in self._order if test(n)}

    @property
    def mesh_nodes(self):
        return self._where(lambda n: n.mesh is not None)

    @property
    def camera_nodes(self):
        return self._where(lambda n: n.camera is not None)

    @property
    def light_nodes(self):
        return self._where(lambda n: n.light is not None)

    @property
    def point_light_nodes(self):
        return self._where(lambda n: isinstance(n.light, PointLight))

    @property
    def spot_light_nodes(self):
        return self._where(lambda n: isinstance(n.light, SpotLight))

    @property
    def directional_light_nodes(self):
        return self._where(lambda n: isinstance(n.light, DirectionalLight))

    @property
    def meshes(self):
        return {n.mesh for n in self.mesh_nodes}

    @property
    def cameras(self):
        return {n.camera for n in self.camera_nodes}

    @property
    def lights(self):
        return {n.light for n in self.light_nodes}

    @property
    def main_camera_node(self):
        return self._main_camera_node

    @main_camera_node.setter
    def main_camera_node(self, value):
        if value not in self._parent:
            raise ValueError("New main camera node must already be in scene")
        if value.camera is None:
            raise ValueError("main_camera_node: the node has no camera")
        self._main_camera_node = value

    def add(self, obj, name=None, pose=None, parent_node=None, parent_name=None):
        """Adds a Mesh, Light or Camera in a new Node at `pose` (relative to the parent)."""
        if isinstance(obj, Mesh):
            node = Node(name=name, matrix=pose, mesh=obj)
        elif isinstance(obj, Light):
            node = Node(name=name, matrix=pose, light=obj)
        elif isinstance(obj, Camera):
            node = Node(name=name, matrix=pose, camera=obj)
        else:
            raise TypeError("Unrecognized object type")
        if parent_node is None and parent_name is not None:
            parents = self.get_nodes(name=parent_name)
            if len(parents) == 0:
                raise ValueError(f"No parent node with name {parent_name} found")
            if len(parents) > 1:
                raise ValueError(f"More than one parent node with name {parent_name} found")
            parent_node = next(iter(parents))
        self.add_node(node, parent_node=parent_node)
        return node

    def add_node(self, node, parent_node=None):
        """Adds `node` and its children under `parent_node` (None: a root)."""
        if not isinstance(node, Node):
            raise TypeError(f"add_node: expected a Node, got {type(node).__name__}")
        if node in self._parent:
            raise ValueError("Node already in scene")
        if parent_node is not None:
            if parent_node not in self._parent:
                raise ValueError("Parent node must already be in scene")
            if node not in parent_node.children:
                parent_node.children.append(node)
        self._parent[node] = parent_node
        self._order.append(node)
        if node.camera is not None and self._main_camera_node is None:
            self._main_camera_node = node
        for child in list(node.children):
            self.add_node(child, node)

    def has_node(self, node):
        return node in self._parent

    def get_nodes(self, node=None, name=None, obj=None, obj_name=None):
        """The nodes matching every term given."""
        if node is not None:
            return {node} if node in self._parent else set()
        out = set(self._order)
        if name is not None:
            out = {n for n in out if n.name == name}
        if obj is not None:
            out = {n for n in out if obj is n.mesh or obj is n.camera or obj is n.light}
        if obj_name is not None:
            out = {n for n in out if any(o is not None and getattr(o, "name", None) == obj_name
                                         for o in (n.mesh, n.camera, n.light))}
        return out

    def get_children(self, parent_node):
        return [n for n in self._order if self._parent[n] is parent_node]

    def remove_node(self, node):
        """Removes `node` and everything below it."""
        if node not in self._parent:
            raise ValueError("Node must already be in scene")
        parent = self._parent[node]
        if parent is not None and node in parent.children:
            parent.children.remove(node)
        gone = set()
        stack = [node]
        while stack:
            n = stack.pop()
            gone.add(n)
            stack.extend(c for c in self._order if self._parent[c] is n)
        self._order = [n for n in self._order if n not in gone]
        for n in gone:
            del self._parent[n]
        if self._main_camera_node in gone:
            cams = [n for n in self._order if n.camera is not None]
            self._main_camera_node = cams[0] if cams else None

    def get_pose(self, node):
        """The node's world pose: its matrix after its parents'."""
        if node not in self._parent:
            raise ValueError("Node must already be in scene")
        pose = node._m
        p = self._parent[node]
        while p is not None:
            pose = p._m @ pose
            p = self._parent[p]
        return pose.copy() if pose is node._m else pose

    def set_pose(self, node, pose):
        """Sets the node's pose relative to its parent."""
        if node not in self._parent:
            raise ValueError("Node must already be in scene")
        node.matrix = pose

    @property
    def bounds(self) -> np.ndarray:
        corners = []
        for n in self._order:
            if n.mesh is None:
                continue
            lo, hi = n.mesh.bounds
            c = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
            pose = self.get_pose(n)
            corners.append(c @ pose[:3, :3].T + pose[:3, 3])
        if not corners:
            return np.zeros((2, 3))
        c = np.vstack(corners)
        return np.array([c.min(axis=0), c.max(axis=0)])

    @property
    def centroid(self):
        return np.mean(self.bounds, axis=0)

    @property
    def extents(self):
        return np.diff(self.bounds, axis=0).reshape(-1)

    @property
    def scale(self):
        return float(np.linalg.norm(self.extents))

    @staticmethod
    def from_trimesh_scene(trimesh_scene, bg_color=None, ambient_light=None):
        """A Scene from a trimesh.Scene (anything with `geometry` and `graph`)."""
        geometries = {name: Mesh.from_trimesh(g) for name, g in trimesh_scene.geometry.items()}
        scene = Scene(bg_color=bg_color, ambient_light=ambient_light)
        for node in trimesh_scene.graph.nodes_geometry:
            pose, geom_name = trimesh_scene.graph[node]
            scene.add(geometries[geom_name], pose=pose)
        return scene


# ---------------------------------------------------------------- rendering
class OffscreenRenderer:
    """pyrender's OffscreenRenderer, rendering on the CPU: no display, GL or EGL.

    OffscreenRenderer(viewport_width, viewport_height, point_size=1.0); Velocity's own
    keywords: ssaa (1..4 samples a side) and threads (cores for a frame; 0: all)."""

    def __init__(self, viewport_width, viewport_height, point_size=1.0, *, ssaa=1, threads=0):
        self._renderer = None
        self.point_size = point_size
        self._renderer = _v.OffscreenRenderer(_size(viewport_width, "viewport_width"),
                                              _size(viewport_height, "viewport_height"), ssaa, threads)

    def _live(self):
        if self._renderer is None:
            raise RuntimeError("OffscreenRenderer: delete() was called; make a new renderer")
        return self._renderer

    @property
    def viewport_width(self):
        return self._live().viewport_width

    @viewport_width.setter
    def viewport_width(self, value):
        self._live().viewport_width = _size(value, "viewport_width")

    @property
    def viewport_height(self):
        return self._live().viewport_height

    @viewport_height.setter
    def viewport_height(self, value):
        self._live().viewport_height = _size(value, "viewport_height")

    @property
    def point_size(self):
        return self._point_size

    @point_size.setter
    def point_size(self, value):
        value = float(value)
        if not (math.isfinite(value) and 1 <= value <= 64):
            raise ValueError(f"point_size: expected 1..64 pixels, got {value}")
        self._point_size = value

    def delete(self):
        """Frees the renderer's buffers; rendering with it afterwards raises."""
        self._renderer = None

    def render(self, scene, flags=RenderFlags.NONE, seg_node_map=None):
        """Renders `scene` from its main camera, as pyrender does: (color, depth), or depth
        alone with DEPTH_ONLY. color: H x W x 3 uint8 (x 4 with RGBA); with SEG the colour
        image is the segmentation (each node of seg_node_map in its colour, black elsewhere;
        nodes not in the map are not drawn). depth: H x W float32 view-axis distance, 0
        where nothing was drawn."""
        renderer = self._live()
        if not isinstance(scene, Scene):
            raise TypeError(f"render: expected a velocity.pyrender.Scene, got {type(scene).__name__}")
        flags = int(flags)  # plain ints from here: IntFlag's operators cost microseconds each
        if flags & _REFUSED_MASK:
            flag = next(f for f in _REFUSED if flags & f)
            raise ValueError(f"render: RenderFlags.{flag.name} is not supported: {_REFUSED[flag]}")
        if scene.main_camera_node is None:
            raise ValueError("render: the scene has no camera (add one with scene.add(camera, pose=...))")
        seg = bool(flags & _SEG)
        unlit = bool(flags & (_FLAT | _SEG))
        native, ids, points = self._frame(scene, flags, seg, unlit, seg_node_map or {})
        native_flags = flags & _NATIVE
        if seg:  # the mask, from which the segmentation colours come; no shadows for it
            native_flags = (native_flags & ~_SHADOWS) | (0 if flags & _DEPTH_ONLY else _SEG)
        # pyrender lights in linear light and writes gamma-encoded pixels, except for FLAT
        # and SEG, which write their colours as they are.
        out = renderer._render(native, native_flags, "display" if unlit else "linear")
        if flags & _DEPTH_ONLY:
            depth = out
            color = mask = None
        elif seg:
            color, depth, mask = out
        else:
            color, depth = out
            mask = None
        if points:
            ids.update(self._draw_points(scene, points, color, depth, mask, max(ids, default=0) + 1))
        if flags & _DEPTH_ONLY:
            return depth
        if seg:
            color = self._segmentation(mask, ids, seg_node_map or {}, color.shape[2])
        return color, depth

    def _frame(self, scene, flags, seg, unlit, seg_node_map):
        """The engine's scene for this frame: (scene, {mask id: node}, point primitives)."""
        bg = (0.0, 0.0, 0.0, 1.0) if seg else scene._bg_native
        native = _v.Scene(bg_color=bg, ambient_light=scene._ambient_native)
        ids: dict = {}
        points = []
        for node in scene._order:
            mesh = node.mesh
            if mesh is None or not mesh.is_visible or (seg and node not in seg_node_map):
                continue
            world = scene.get_pose(node)
            for prim in mesh.primitives:
                if prim.mode == GLTF.POINTS:
                    points.append((node, prim, world))
                    continue
                wire = prim.material.wireframe
                if flags & _FLIP_WIREFRAME:
                    wire = not wire
                if flags & _ALL_SOLID:
                    wire = False
                m = prim._native(wire, unlit)
                if prim.poses is None:
                    ids[native.add(m, pose=world).id] = node
                else:
                    for p in prim.poses:
                        ids[native.add(m, pose=world @ p).id] = node
        if not (unlit or flags & _DEPTH_ONLY):
            for node in scene._order:
                if node.light is not None:
                    native.add(node.light._native(), pose=scene.get_pose(node))
        cam = scene.main_camera_node
        native.add(cam.camera._native(), pose=scene.get_pose(cam))
        return native, ids, points

    def _segmentation(self, mask, ids, seg_node_map, channels):
        """pyrender's segmentation image: each node's colour from seg_node_map (0..255,
        one number for grey), black where none."""
        lut = np.zeros((max(ids, default=0) + 1, channels), dtype=np.uint8)
        if channels == 4:
            lut[:, 3] = 255
        for i, node in ids.items():
            c = seg_node_map[node]
            c = np.repeat(c, 3) if np.ndim(c) == 0 else np.asarray(c)[:3]
            lut[i, :3] = np.clip(np.asarray(c, dtype=np.float64), 0, 255).astype(np.uint8)
        return lut[np.minimum(mask, len(lut) - 1)]

    def _draw_points(self, scene, points, color, depth, mask, next_id):
        """Point clouds, drawn here (the engine draws a mesh's points in one colour):
        each point a point_size square in its colour, unlit, depth-tested against the
        engine's depth image, nearest first. Returns {mask id: node} for what it drew."""
        cam_node = scene.main_camera_node
        h, w = depth.shape
        proj = cam_node.camera.get_projection_matrix(w, h)
        view = np.linalg.inv(scene.get_pose(cam_node))
        ids = {}
        half = (self.point_size - 1) / 2
        for node, prim, world in points:
            poses = prim.poses if prim.poses is not None else np.eye(4)[None]
            for p in poses:
                pts = np.c_[prim.positions.astype(np.float64), np.ones(len(prim.positions))]
                eye = pts @ (view @ world @ p).T
                clip = eye @ proj.T
                z = -eye[:, 2]
                ok = (clip[:, 3] > 0) & (np.abs(clip[:, 2]) <= clip[:, 3]) if cam_node.camera.zfar is not None \
                    else (clip[:, 3] > 0) & (clip[:, 2] >= -clip[:, 3])
                ndc = clip[ok, :2] / clip[ok, 3:4]
                px = (ndc[:, 0] + 1) * 0.5 * w
                py = (1 - ndc[:, 1]) * 0.5 * h
                zs = z[ok].astype(np.float32)
                cols = None
                if color is not None:
                    base = prim.material._base()[0][:3]
                    c = prim.color_0[ok, :3] * base if prim.color_0 is not None else np.tile(base, (len(zs), 1))
                    cols = np.clip(np.rint(c * 255), 0, 255).astype(np.uint8)
                for dy in np.arange(-half, half + 1):
                    for dx in np.arange(-half, half + 1):
                        x = np.floor(px + dx).astype(np.int64)
                        y = np.floor(py + dy).astype(np.int64)
                        inside = (x >= 0) & (x < w) & (y >= 0) & (y < h)
                        xi, yi, zi = x[inside], y[inside], zs[inside]
                        order = np.argsort(-zi, kind="stable")  # far first: the nearest is written last
                        xi, yi, zi = xi[order], yi[order], zi[order]
                        d = depth[yi, xi]
                        front = (d == 0) | (zi <= d)
                        xi, yi, zi = xi[front], yi[front], zi[front]
                        depth[yi, xi] = zi
                        if cols is not None:
                            ci = cols[inside][order][front]
                            color[yi, xi, :3] = ci
                            if color.shape[2] == 4:
                                color[yi, xi, 3] = 255
                        if mask is not None:
                            mask[yi, xi] = next_id
                if mask is not None:
                    ids[next_id] = node
                    next_id += 1
        return ids


class Viewer:
    """pyrender's interactive Viewer needs a window and OpenGL; Velocity's module renders
    offscreen only. Constructing one raises, saying what to use instead."""

    def __init__(self, scene=None, viewport_size=None, render_flags=None, viewer_flags=None,
                 registered_keys=None, run_in_thread=False, **kwargs):
        raise NotImplementedError("velocity.pyrender has no Viewer (no window here): render with "
                                  "OffscreenRenderer(w, h).render(scene), or view models with `velocity view`")


def _size(value, what):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise TypeError(f"{what}: expected an integer number of pixels, got {value!r}")
    value = int(value)
    if not 1 <= value <= 16384:
        raise ValueError(f"{what}: expected 1..16384 pixels, got {value}")
    return value
