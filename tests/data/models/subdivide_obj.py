#!/usr/bin/env python3
"""Midpoint-subdivides every triangle of an OBJ file into four (positions only).

Used once to make wuson_x4.obj (14,928 triangles) from Assimp's WusonOBJ.obj test model
(Debian package assimp-testmodels, /usr/share/assimp/models/OBJ/WusonOBJ.obj, BSD-3-Clause,
see LICENSES.md): a real, non-convex model with more than 10,000 triangles for the golden
tests. Edge midpoints are shared, so the result is as welded as the input. The shape is
unchanged (the new vertices lie on the old faces); only the triangle count grows.

    python3 subdivide_obj.py WusonOBJ.obj > wuson_x4.obj
"""
import sys

def main(path):
    verts, faces = [], []
    for line in open(path, encoding="latin-1"):
        p = line.split()
        if not p:
            continue
        if p[0] == "v":
            verts.append(tuple(float(x) for x in p[1:4]))
        elif p[0] == "f":
            idx = [int(t.split("/")[0]) for t in p[1:]]
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            for k in range(1, len(idx) - 1):
                faces.append((idx[0], idx[k], idx[k + 1]))
    mid = {}
    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            va, vb = verts[a], verts[b]
            verts.append(tuple((x + y) / 2 for x, y in zip(va, vb)))
            mid[key] = len(verts) - 1
        return mid[key]
    out = []
    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    w = sys.stdout.write
    w("# Assimp test model WusonOBJ.obj (BSD-3-Clause, ASSIMP Development Team),\n")
    w("# each triangle midpoint-subdivided into four by subdivide_obj.py\n")
    for v in verts:
        w("v %.6f %.6f %.6f\n" % v)
    for a, b, c in out:
        w("f %d %d %d\n" % (a + 1, b + 1, c + 1))

if __name__ == "__main__":
    main(sys.argv[1])
