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


# A renderer made and used (its worker threads started) before fork(): the child has
# none of those threads. It must render the same image there, never wait for them.
_parent_renderer = None


def render_with_parents_renderer(i):
    scene, _ = simple_scene(velocity.Mesh.torus(), pose=velocity.look_at([0.2 * i, 1, 3], [0, 0, 0]))
    return _parent_renderer.render(scene, velocity.RenderFlags.SEG)


@pytest.mark.skipif(SANITIZER == "tsan", reason="TSan does not support fork() after threads")
def test_renderer_made_before_fork_works_in_the_child():
    global _parent_renderer
    _parent_renderer = velocity.OffscreenRenderer(80, 60, threads=3)
    expected = [render_with_parents_renderer(i) for i in range(3)]  # the pool's threads are running
    ctx = mp.get_context("fork")
    with ctx.Pool(2) as pool:
        pending = pool.map_async(render_with_parents_renderer, range(3))
        results = pending.get(timeout=120)  # a hang fails here instead of blocking forever
    for got, want in zip(results, expected):
        assert all(np.array_equal(g, w) for g, w in zip(got, want))
    # And in a bare os.fork() child, which then exits without Python's clean-up.
    import os
    import time
    time.sleep(0.05)  # the renderer's workers past their spinning, asleep
    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            code = 0 if all(np.array_equal(g, w) for g, w in zip(render_with_parents_renderer(0), expected[0])) else 2
        finally:
            os._exit(code)
    deadline = time.monotonic() + 120
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            break
        if time.monotonic() > deadline:
            os.kill(pid, 9)
            os.waitpid(pid, 0)
            pytest.fail("the forked child hung rendering with its parent's renderer")
        time.sleep(0.01)
    assert os.waitstatus_to_exitcode(status) == 0
