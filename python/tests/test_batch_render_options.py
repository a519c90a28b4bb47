"""The batch job's renderer: `backend` and the appearance options (color, tone_map,
exposure, shadows, shadow_map_size, point_size) as job keys and `velocity batch`
flags, checked like the rest of the job, reaching each worker's renderer. The GPU runs
(llvmpipe here) only where VELOCITY_GPU_LIBRARY is set: the gpu-labelled ctest
(tests/gpu/CMakeLists.txt, gpu_python_batch)."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import model
from velocity.batch import run_local
from velocity.jobs import JobError, load_job
from velocity.png import decode_png
from velocity.progress import Progress
from velocity.tasks import plan_tasks

GPU = bool(os.environ.get("VELOCITY_GPU_LIBRARY"))


def job_file(tmp_path, **keys):
    spec = {"models": [model("duck.asc")], "size": [48, 36], "views": {"type": "orbit", "count": 3},
            "outputs": ["color", "depth", "mask"], "bg_color": [0, 0, 0, 1], "output": "out"}
    spec.update(keys)
    path = tmp_path / "job.json"
    path.write_text(json.dumps(spec))
    return str(path)


def batch(*args, env=None):
    return subprocess.run([sys.executable, "-m", "velocity.batch", "--progress", "never", *args],
                          capture_output=True, text=True, env={**os.environ, **(env or {})})


def colors(out, count=3):
    return [decode_png((out / "duck" / f"{v:06d}.color.png").read_bytes()) for v in range(count)]


def masks(out, count=3):
    return [decode_png((out / "duck" / f"{v:06d}.mask.png").read_bytes()) for v in range(count)]


def test_defaults_and_keys():
    job = load_job({"models": [model("duck.asc")], "output": "x"})
    s = job.spec
    assert (s["backend"], s["color"], s["tone_map"], s["exposure"], s["shadows"], s["shadow_map_size"],
            s["point_size"]) == ("cpu", "auto", "none", 1.0, False, 2048, 1.0)
    job = load_job({"models": [model("duck.asc")], "output": "x", "backend": "auto", "color": "linear",
                    "tone_map": "neutral", "exposure": 2, "shadows": True, "shadow_map_size": 1024, "point_size": 3})
    assert (job.spec["backend"], job.spec["tone_map"], job.spec["exposure"], job.spec["point_size"]) == \
        ("auto", "neutral", 2.0, 3.0)


@pytest.mark.parametrize("key,value,words", [
    ("backend", "opengl", "job.backend: expected cpu, gpu, auto, got 'opengl'"),
    ("color", "srgb", "job.color: expected auto, linear, display"),
    ("tone_map", "filmic", "job.tone_map: expected none, aces, neutral"),
    ("exposure", -0.5, "job.exposure: expected a finite number"),
    ("exposure", "1", "job.exposure: expected a number"),
    ("shadows", "yes", "job.shadows: expected true or false"),
    ("shadow_map_size", 4, "job.shadow_map_size: expected a finite number in [16, 8192]"),
    ("shadow_map_size", 512.5, "job.shadow_map_size: expected an integer"),
    ("point_size", 100, "job.point_size: expected a finite number in [1.0, 64.0]"),
])
def test_bad_values_are_one_line_job_errors(tmp_path, key, value, words):
    with pytest.raises(JobError, match=None) as e:
        load_job(job_file(tmp_path, **{key: value}))
    assert words in str(e.value)
    run = batch(job_file(tmp_path, **{key: value}))
    assert run.returncode == 1 and run.stderr.count("\n") == 1 and words in run.stderr


def test_unchanged_defaults_keep_the_task_hashes(tmp_path):
    # A job from before these keys existed resumes; the backend never re-renders a view,
    # a changed look does.
    plain = plan_tasks(load_job(job_file(tmp_path)))
    explicit = plan_tasks(load_job(job_file(tmp_path, color="auto", exposure=1.0, shadows=False, backend="gpu")))
    darker = plan_tasks(load_job(job_file(tmp_path, exposure=0.5)))
    assert [t.hash for t in plain] == [t.hash for t in explicit]
    assert [t.hash for t in plain] != [t.hash for t in darker]


def test_job_keys_and_flags_reach_the_renderer(tmp_path):
    lit = run_local(load_job(job_file(tmp_path)), progress=Progress(False))
    assert lit["views_done"] == 3
    base = colors(tmp_path / "out")
    # exposure 0 in the linear pipeline: no light at all, the background black.
    dark_out = tmp_path / "dark"
    run = batch(job_file(tmp_path, color="linear"), "--out", str(dark_out), "--exposure", "0")
    assert run.returncode == 0, run.stderr
    assert all(img.max() == 0 for img in colors(dark_out)) and all(img.max() > 100 for img in base)
    assert all(np.array_equal(a, b) for a, b in zip(masks(dark_out), masks(tmp_path / "out")))
    # The flag wins over the job's key; --no-shadows and --shadows both parse.
    aces_out = tmp_path / "aces"
    run = batch(job_file(tmp_path, tone_map="neutral"), "--out", str(aces_out), "--color", "linear",
                "--tone-map", "aces", "--no-shadows", "--shadow-map-size", "256", "--point-size", "2")
    assert run.returncode == 0, run.stderr
    neutral_out = tmp_path / "neutral"
    assert batch(job_file(tmp_path, tone_map="neutral", color="linear"), "--out", str(neutral_out)).returncode == 0
    assert not all(np.array_equal(a, b) for a, b in zip(colors(aces_out), colors(neutral_out)))


def test_a_gpu_backend_that_cannot_start_is_one_line(tmp_path):
    run = batch(job_file(tmp_path), "--backend", "gpu", env={"VELOCITY_GPU_LIBRARY": "/nonexistent/libvelocity-gpu.so"})
    assert run.returncode == 1 and run.stderr.count("\n") == 1
    assert run.stderr.startswith("velocity-batch: backend gpu: the GPU backend is not available")
    assert not (tmp_path / "out" / "duck").exists()


@pytest.mark.skipif(not GPU, reason="the GPU backend's tests run in gpu_python_batch (VELOCITY_GPU_LIBRARY)")
@pytest.mark.parametrize("workers", [1, 2])
def test_gpu_backend_renders_the_same_views(tmp_path, workers):
    cpu_out, gpu_out = tmp_path / "cpu", tmp_path / "gpu"
    assert batch(job_file(tmp_path), "--out", str(cpu_out)).returncode == 0
    run = batch(job_file(tmp_path, backend="gpu"), "--out", str(gpu_out), "--workers", str(workers))
    assert run.returncode == 0, run.stderr
    manifest = json.loads((gpu_out / "manifest.json").read_text())
    assert manifest["views_done"] == 3 and not manifest["models_failed"]
    for c, g in zip(masks(cpu_out), masks(gpu_out)):
        assert (c == g).mean() > 0.99  # silhouettes: each rasterizer snaps edges its own way
    for c, g in zip(colors(cpu_out), colors(gpu_out)):
        mse = np.mean((c.astype(float) - g.astype(float)) ** 2)
        assert 10 * np.log10(255 ** 2 / max(mse, 1e-9)) > 30
