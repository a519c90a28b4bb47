"""Renderers in processes started by multiprocessing (spawn and fork)."""
import multiprocessing as mp

import numpy as np
import pytest

import velocity
from conftest import SANITIZER, simple_scene


def render_one(i):
    scene, _ = simple_scene(velocity.Mesh.torus(), pose=velocity.look_at([0.2 * i, 1, 3], [0, 0, 0]))
    color, depth, mask = velocity.OffscreenRenderer(80, 60, threads=1).render(scene, velocity.RenderFlags.SEG)
    return i, color, depth, mask


# fork after the sanitizer runtimes have started threads is not supported by TSan.
METHODS = ["spawn"] + ([] if SANITIZER == "tsan" else ["fork"])


@pytest.mark.parametrize("method", METHODS)
def test_pool_of_processes_renders_what_this_process_does(method):
    with mp.get_context(method).Pool(2) as pool:
        results = pool.map(render_one, range(4))
    for i, color, depth, mask in results:
        _, c, d, m = render_one(i)
        assert np.array_equal(color, c) and np.array_equal(depth, d) and np.array_equal(mask, m)
