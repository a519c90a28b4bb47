"""Many renderers at once from many threads; the GIL is released while rendering."""
import threading

import numpy as np

import velocity
from conftest import simple_scene


def scene_for(i):
    pose = velocity.look_at([np.sin(i), 0.3 * i % 1, 3], [0, 0, 0])
    return simple_scene(velocity.Mesh.torus(), pose=pose)[0]


def test_many_threads_render_the_same_as_one():
    n = 6
    expected = [velocity.OffscreenRenderer(96, 64, threads=1).render(scene_for(i), velocity.RenderFlags.SEG)
                for i in range(n)]
    results = [None] * n
    errors = []

    def work(i):
        try:
            r = velocity.OffscreenRenderer(96, 64, threads=2)
            for _ in range(5):
                results[i] = r.render(scene_for(i), velocity.RenderFlags.SEG)
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for got, want in zip(results, expected):
        for g, w in zip(got, want):
            assert np.array_equal(g, w)


def test_one_renderer_shared_by_threads_is_serialised():
    scene = scene_for(1)
    r = velocity.OffscreenRenderer(64, 48)
    want = r.render(scene)[1]
    out = []
    ts = [threading.Thread(target=lambda: out.append(r.render(scene)[1])) for _ in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    assert len(out) == 4 and all(np.array_equal(o, want) for o in out)


def test_the_gil_is_released_while_rendering():
    # While one thread renders a large frame, another Python thread must keep running:
    # count its loop iterations that fall between the start and end of render() calls.
    scene = simple_scene(velocity.Mesh.sphere(256))[0]
    r = velocity.OffscreenRenderer(1280, 960, threads=1)
    stop = threading.Event()
    ticks = []

    def spin():
        while not stop.is_set():
            ticks.append(threading.get_native_id() and len(ticks))

    calls = []
    t = threading.Thread(target=spin)
    t.start()
    try:
        for _ in range(3):
            before = len(ticks)
            r.render(scene, velocity.RenderFlags.NORMALS)
            calls.append(len(ticks) - before)
    finally:
        stop.set()
        t.join()
    # With the GIL held for the whole call the spinning thread could not run at all
    # inside it (0 iterations); released, it runs thousands of times.
    assert max(calls) > 100, calls


def test_scene_may_change_while_another_thread_renders():
    scene, node = simple_scene(velocity.Mesh.sphere(128))
    r = velocity.OffscreenRenderer(320, 240)
    done = threading.Event()
    errors = []

    def render():
        try:
            for _ in range(10):
                r.render(scene, velocity.RenderFlags.SEG)
        except Exception as e:  # pragma: no cover
            errors.append(e)
        done.set()

    t = threading.Thread(target=render)
    t.start()
    i = 0
    while not done.is_set():
        pose = np.eye(4)
        pose[0, 3] = 0.001 * (i % 100)
        scene.set_pose(node, pose)
        extra = scene.add(velocity.Mesh.cube(0.1))
        scene.remove_node(extra)
        i += 1
    t.join()
    assert not errors and i > 0
