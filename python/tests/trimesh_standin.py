"""Stand-ins for trimesh objects (trimesh is not a Debian package): plain classes with
the attributes pyrender's Mesh.from_trimesh reads, built the way trimesh builds them."""
from __future__ import annotations

import numpy as np


class Visual:
    def __init__(self, kind=None, vertex_colors=None, face_colors=None, uv=None, material=None):
        self.kind, self.vertex_colors, self.face_colors, self.uv, self.material = (
            kind, vertex_colors, face_colors, uv, material)
        self.defined = kind is not None


class SimpleMaterial:
    """trimesh.visual.material.SimpleMaterial: a diffuse colour, an image, the MTL's keys."""

    def __init__(self, image=None, diffuse=(255, 255, 255, 255), Ns=None):
        self.image, self.diffuse = image, np.asarray(diffuse, dtype=np.uint8)
        self.kwargs = {} if Ns is None else {"Ns": Ns}


class Trimesh:
    def __init__(self, vertices, faces, vertex_normals=None, visual=None):
        self.vertices = np.asarray(vertices, dtype=np.float64)
        self.faces = np.asarray(faces, dtype=np.int64)
        a, b, c = (self.vertices[self.faces[:, k]] for k in range(3))
        n = np.cross(b - a, c - a)
        self.face_normals = n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
        if vertex_normals is None:  # area-weighted, as trimesh's
            vn = np.zeros_like(self.vertices)
            for k in range(3):
                np.add.at(vn, self.faces[:, k], n)
            vertex_normals = vn / np.maximum(np.linalg.norm(vn, axis=1, keepdims=True), 1e-30)
        self.vertex_normals = np.asarray(vertex_normals, dtype=np.float64)
        self.visual = visual if visual is not None else Visual()


def load_obj(path, image=None):
    """An OBJ file as trimesh.load reads one with a texture: a vertex per distinct
    (v, vt, vn) corner, uvs as the file writes them (v up from the image's bottom)."""
    v, vt, vn, corners = [], [], [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                v.append([float(x) for x in w[1:4]])
            elif w[0] == "vt":
                vt.append([float(x) for x in w[1:3]])
            elif w[0] == "vn":
                vn.append([float(x) for x in w[1:4]])
            elif w[0] == "f":
                corners.append([tuple(int(i) - 1 for i in c.split("/")) for c in w[1:4]])
    index: dict = {}
    faces = [[index.setdefault(c, len(index)) for c in face] for face in corners]
    keys = sorted(index, key=index.get)
    verts = np.array([v[k[0]] for k in keys])
    uv = np.array([vt[k[1]] for k in keys])
    normals = np.array([vn[k[2]] for k in keys])
    visual = Visual(kind="texture", uv=uv, material=SimpleMaterial(image=image, Ns=0.0))
    return Trimesh(verts, faces, normals, visual)


def box(extents=(1.0, 1.0, 1.0)):
    """trimesh.creation.box: 8 vertices, 12 outward triangles, centred on the origin."""
    e = np.asarray(extents, dtype=np.float64) / 2
    verts = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64) * e
    faces = np.array([[1, 3, 0], [4, 1, 0], [0, 3, 2], [2, 4, 0], [1, 7, 3], [5, 1, 4],
                      [5, 7, 1], [3, 7, 2], [6, 4, 2], [2, 7, 6], [6, 5, 4], [7, 5, 6]])
    return Trimesh(verts, faces)
