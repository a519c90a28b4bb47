"""pyrender's offscreen quickstart rendered by velocity.pyrender, compared with the image
pyrender's repository publishes for it (its documentation's minexcolor.png, copied to
python/tests/data/pyrender/). Prints the PSNR and the silhouette's overlap.

    PYTHONPATH=build/python:python/tests python3 python/bench/compare_quickstart.py [out.png]
"""
import os
import sys

import numpy as np
from PIL import Image

import velocity.pyrender as pyrender
import trimesh_standin as trimesh

DATA = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "pyrender")

fuze_trimesh = trimesh.load_obj(os.path.join(DATA, "fuze.obj"), Image.open(os.path.join(DATA, "fuze_uv.jpg")))
mesh = pyrender.Mesh.from_trimesh(fuze_trimesh)
scene = pyrender.Scene()
scene.add(mesh)
camera = pyrender.PerspectiveCamera(yfov=np.pi / 3.0, aspectRatio=1.0)
s = np.sqrt(2) / 2
camera_pose = np.array([[0.0, -s, s, 0.3], [1.0, 0.0, 0.0, 0.0], [0.0, s, s, 0.35], [0.0, 0.0, 0.0, 1.0]])
scene.add(camera, pose=camera_pose)
light = pyrender.SpotLight(color=np.ones(3), intensity=3.0, innerConeAngle=np.pi / 16.0, outerConeAngle=np.pi / 6.0)
scene.add(light, pose=camera_pose)
color, depth = pyrender.OffscreenRenderer(400, 400).render(scene)

ref = np.asarray(Image.open(os.path.join(DATA, "minexcolor.png")).convert("RGB")).astype(np.float64)
mse = np.mean((color.astype(np.float64) - ref) ** 2)
ours, theirs = depth > 0, (ref < 250).any(axis=2)
both = ours & theirs
print(f"PSNR {10 * np.log10(255.0 ** 2 / mse):.2f} dB over the image; "
      f"silhouette IoU {both.sum() / (ours | theirs).sum():.3f}; "
      f"mean colour on the bottle: ours {color[both].mean(axis=0).round(1)}, pyrender's {ref[both].mean(axis=0).round(1)}")
if len(sys.argv) > 1:
    Image.fromarray(color).save(sys.argv[1])
