"""velocity-batch on one machine: outputs, manifest, atomic writes, resume, bad models."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import model
from velocity.batch import run_local
from velocity.jobs import load_job
from velocity.progress import Progress
from velocity.png import decode_png


def make_job(tmp_path, models=None, **kw):
    bad = tmp_path / "broken.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nf 1 2 7\n")  # a face with a vertex that does not exist
    spec = {"models": models or [model("duck.asc"), str(bad), model("fork.asc")],
            "size": [48, 36], "views": {"type": "orbit", "count": 4, "elevation_deg": [10, 50]},
            "outputs": ["color", "depth", "mask", "normals"], "chunk": 3}
    spec.update(kw)
    path = tmp_path / "job.json"
    path.write_text(json.dumps(spec))
    return str(path)


def files_under(root):
    return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs)


def test_job_renders_everything_reports_bad_model_and_resumes(tmp_path):
    out = tmp_path / "out"
    job = load_job(make_job(tmp_path), str(out))
    manifest = run_local(job, progress=Progress(False))
    assert manifest["views_total"] == 24 and manifest["views_done"] == 16
    assert manifest["models_failed"] == ["broken"]
    err = manifest["models"]["broken"]["errors"][0]
    assert "broken.obj: index out of range" in err  # the engine's message
    duck = manifest["models"]["duck"]
    assert duck["status"] == "done" and len(duck["views"]) == 8
    view = duck["views"]["5"]
    assert np.array(view["camera_pose"]).shape == (4, 4) and np.array(view["projection"]).shape == (4, 4)
    color = decode_png((out / view["files"]["color"]).read_bytes())
    depth = np.load(out / view["files"]["depth"])
    mask = decode_png((out / view["files"]["mask"]).read_bytes())
    normals = np.load(out / view["files"]["normals"])
    assert color.shape == (36, 48, 3) and depth.shape == (36, 48) and normals.shape == (36, 48, 3)
    assert mask.dtype == np.uint16 and set(np.unique(mask)) == {0, 1}
    assert np.array_equal(mask > 0, depth > 0) and (depth > 0).sum() > 20
    assert os.listdir(out / ".velocity" / "tmp") == []  # nothing half-written is left

    # Second run: everything done is skipped (files untouched), the bad model is tried again.
    before = {f: os.stat(out / f).st_mtime_ns for f in files_under(out) if f.startswith("duck/")}
    manifest2 = run_local(load_job(make_job(tmp_path), str(out)), progress=Progress(False))
    assert manifest2["views_done"] == 16 and manifest2["models_failed"] == ["broken"]
    assert before == {f: os.stat(out / f).st_mtime_ns for f in before}

    # A file lost since: only its view is rendered again.
    os.unlink(out / duck["views"]["4"]["files"]["depth"])
    run_local(load_job(make_job(tmp_path), str(out)), progress=Progress(False))
    assert os.path.exists(out / duck["views"]["4"]["files"]["depth"])
    assert os.stat(out / duck["views"]["0"]["files"]["color"]).st_mtime_ns == before[duck["views"]["0"]["files"]["color"]]


def test_interrupted_task_resumes_where_it_stopped(tmp_path):
    out = tmp_path / "out"
    path = make_job(tmp_path, models=[model("duck.asc")], chunk=0)

    class Stop(BaseException):
        pass

    def stop_at_view_5(job, task, view):
        if view == 5:
            raise Stop  # as if the process died here: the task never finishes

    with pytest.raises(Stop):
        run_local(load_job(path, str(out)), progress=Progress(False), hooks={"before_view": stop_at_view_5})
    record = json.loads((out / ".velocity" / "tasks" / "duck.json").read_text())
    assert record["status"] == "running"
    done = {f: os.stat(out / f).st_mtime_ns for f in files_under(out) if f.startswith("duck/")}
    assert len(done) == 5 * 4  # views 0..4, four files each
    manifest = run_local(load_job(path, str(out)), progress=Progress(False))
    assert manifest["complete"] and manifest["views_done"] == 8
    assert all(os.stat(out / f).st_mtime_ns == t for f, t in done.items())  # not rendered again


def test_changed_settings_render_again(tmp_path):
    out = tmp_path / "out"
    run_local(load_job(make_job(tmp_path, models=[model("fork.asc")]), str(out)), progress=Progress(False))
    first = decode_png((out / "fork" / "000000.color.png").read_bytes())
    run_local(load_job(make_job(tmp_path, models=[model("fork.asc")], size=[40, 30]), str(out)), progress=Progress(False))
    assert decode_png((out / "fork" / "000000.color.png").read_bytes()).shape == (30, 40, 3) != first.shape


def test_workers_in_processes_give_the_same_files(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    path = make_job(tmp_path, models=[model("duck.asc"), model("fork.asc")])
    run_local(load_job(path, str(a)), workers=1, progress=Progress(False))
    run_local(load_job(path, str(b)), workers=2, progress=Progress(False))
    names = [f for f in files_under(a) if not f.startswith(".velocity") and f != "manifest.json"]
    assert names == [f for f in files_under(b) if not f.startswith(".velocity") and f != "manifest.json"]
    for f in names:
        assert (a / f).read_bytes() == (b / f).read_bytes(), f


def test_a_pool_keeps_its_workers_for_several_jobs(tmp_path):
    from velocity.batch import LocalPool

    path = make_job(tmp_path, models=[model("duck.asc"), model("fork.asc")])
    ref = tmp_path / "ref"
    run_local(load_job(path, str(ref)), workers=1, progress=Progress(False))
    workers = []
    with LocalPool(2) as pool:
        for name in ("a", "b"):
            m = run_local(load_job(path, str(tmp_path / name)), pool=pool, progress=Progress(False))
            assert m["complete"] and m["views_done"] == 16
            records = [json.loads(p.read_text()) for p in (tmp_path / name / ".velocity" / "tasks").iterdir()]
            workers.append({r["worker"] for r in records})
            for f in files_under(ref):
                if not f.startswith(".velocity") and f != "manifest.json":
                    assert (ref / f).read_bytes() == (tmp_path / name / f).read_bytes(), f
    # Both jobs ran in the same processes, none of them this one.
    assert workers[0] == workers[1] and 1 <= len(workers[0]) <= 2
    assert not any(w.endswith(f":{os.getpid()}") for w in workers[0])
    from velocity.jobs import JobError
    with pytest.raises(JobError, match="at least 1"):
        LocalPool(0)


def test_command_line(tmp_path):
    path = make_job(tmp_path, models=[model("fork.asc"), str(tmp_path / "broken.obj")], output="renders")
    env = dict(os.environ)
    p = subprocess.run([sys.executable, "-m", "velocity.batch", path], capture_output=True, text=True, env=env)
    # Not a terminal: no progress bar; a failed model: exit 3 and a one-line summary.
    assert p.returncode == 3, p.stderr
    assert "\r" not in p.stderr and "1 model(s) failed: broken" in p.stderr
    assert json.loads((tmp_path / "renders" / "manifest.json").read_text())["views_done"] == 8
    p = subprocess.run([sys.executable, "-m", "velocity.batch", path, "--progress", "always"],
                       capture_output=True, text=True, env=env)
    assert "8/16" in p.stderr and "16/16" in p.stderr and "view/s" in p.stderr  # tqdm: done/total, rate, ETA
    p = subprocess.run([sys.executable, "-m", "velocity.batch", str(tmp_path / "nope.json")], capture_output=True,
                       text=True)
    assert p.returncode == 1 and "cannot read the job file" in p.stderr
    p = subprocess.run([sys.executable, "-m", "velocity.batch", "--help"], capture_output=True, text=True)
    assert p.returncode == 0 and "--dask" in p.stdout


def test_one_runner_per_output_folder(tmp_path):
    import fcntl

    out = tmp_path / "out"
    (out / ".velocity").mkdir(parents=True)
    with open(out / ".velocity" / "lock", "w") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        from velocity.jobs import JobError
        with pytest.raises(JobError, match="another velocity batch run"):
            run_local(load_job(make_job(tmp_path), str(out)), progress=Progress(False))


def test_progress_bar_counts_views(tmp_path):
    import io
    stream = io.StringIO()
    job = load_job(make_job(tmp_path, models=[model("duck.asc")]), str(tmp_path / "out"))
    run_local(job, progress=Progress(True, stream))
    text = stream.getvalue()
    assert "8/8" in text and "view" in text  # tqdm's bar: 8 views of 8
    stream = io.StringIO()
    run_local(job, progress=Progress(True, stream))  # resumed: all done already
    assert "8/8" in stream.getvalue()
