"""The batch job format: parsing, checks with clear messages, tasks and camera set-up."""
import json
import random

import numpy as np
import pytest

from conftest import model
from velocity.jobs import JobError, load_job
from velocity.tasks import plan_tasks
from velocity.views import view_poses


def job(**kw):
    spec = {"models": [model("duck.asc")], "output": "/tmp/x"}
    spec.update(kw)
    return spec


def test_defaults_and_tasks(tmp_path):
    j = load_job(job(views={"type": "orbit", "count": 8, "elevation_deg": [10, 40]}, chunk=5))
    assert j.view_count() == 16
    tasks = plan_tasks(j)
    assert [(t.start, t.stop) for t in tasks] == [(0, 5), (5, 10), (10, 15), (15, 16)]
    assert len({t.hash for t in tasks}) == 4 and tasks[0].id == "duck.000000-000005"
    # A change of any setting changes the hash (so resumed work is redone), a change of
    # the chunking alone changes the ids.
    j2 = load_job(job(views={"type": "orbit", "count": 8, "elevation_deg": [10, 40]}, chunk=5, size=[64, 64]))
    assert plan_tasks(j2)[0].hash != tasks[0].hash


def test_job_file_relative_globs_and_name_clashes(tmp_path):
    for d in ("a", "b"):
        (tmp_path / d).mkdir()
        (tmp_path / d / "m.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    p = tmp_path / "job.json"
    p.write_text(json.dumps({"models": ["*/m.obj"], "output": "out"}))
    j = load_job(str(p))
    assert j.output == str(tmp_path / "out")
    keys = [k for k, _ in j.models]
    assert len(set(keys)) == 2 and all(k.startswith("m-") for k in keys)


@pytest.mark.parametrize("spec, message", [
    ({"models": []}, "job.models"),
    ({"models": ["nothing-here-*.obj"], "output": "o"}, "matches no file"),
    (job(size=[0, 10]), "job.size"),
    (job(outputs=["color", "colour"]), "job.outputs"),
    (job(camera={"type": "fisheye"}), "camera.type"),
    (job(camera={"type": "intrinsics", "fx": 10}), "camera.fy: required"),
    (job(camera={"type": "perspective", "yfov_deg": 0}), "camera.yfov_deg"),
    (job(views={"type": "orbit", "count": 0}), "views.count"),
    (job(views={"type": "poses", "poses": [[[1, 0, 0, 0]]]}), r"views.poses\[0\]"),
    (job(views={"type": "animation", "frames": 10, "keyframes": [{"frame": 12}]}), r"keyframes\[0\].frame"),
    (job(views={"type": "orbit", "spin": 1}), "unknown key 'spin'"),
    (job(ssaa=9), "job.ssaa"),
    (job(version=2), "job.version"),
    (job(light={"type": "directional", "direction": [0, 0, 0]}), "light.direction"),
    ({"models": ["x.obj"]}, "job.output"),
])
def test_bad_jobs_say_what_is_wrong(spec, message):
    with pytest.raises(JobError, match=message):
        load_job(spec)


def test_bad_job_files(tmp_path):
    p = tmp_path / "job.json"
    p.write_text('{"models": ["a.obj"],\n "size": [1, 2,]}')
    with pytest.raises(JobError, match=r"job.json:2:\d+: not valid JSON"):
        load_job(str(p))
    with pytest.raises(JobError, match="cannot read"):
        load_job(str(tmp_path / "missing.json"))


def test_mutated_jobs_never_crash():
    # A small fuzz of the parser: each mutation of a valid job loads or raises JobError.
    base = job(views={"type": "animation", "frames": 5, "keyframes": [{"frame": 0}, {"frame": 4, "scale": 2}]},
               camera={"type": "intrinsics", "fx": 10, "fy": 10, "cx": 5, "cy": 5})
    rng = random.Random(7)
    values = [None, 0, -1, 1e308, float("nan"), "x", [], {}, [1, 2], True, [[0] * 4] * 4]

    def mutate(x):
        if isinstance(x, dict) and x:
            k = rng.choice(list(x))
            x[k] = mutate(x[k]) if rng.random() < 0.6 else rng.choice(values)
        elif isinstance(x, list) and x:
            i = rng.randrange(len(x))
            x[i] = mutate(x[i]) if rng.random() < 0.6 else rng.choice(values)
        return x

    for _ in range(500):
        spec = mutate(json.loads(json.dumps(base)))
        try:
            load_job(spec)
        except JobError:
            pass


def test_animation_interpolates_between_keyframes():
    j = load_job(job(views={"type": "animation", "frames": 5, "keyframes": [
        {"frame": 0, "translation": [0, 0, 0]}, {"frame": 4, "translation": [4, 0, 0], "rotation_deg": [0, 180, 0]}]}))
    _, m2 = view_poses(j, 2, np.zeros(3), 1.0)
    assert np.allclose(m2[:3, 3], [2, 0, 0])
    assert np.allclose(m2[:3, :3], [[0, 0, 1], [0, 1, 0], [-1, 0, 0]], atol=1e-12)  # 90 degrees about Y
