"""The same job on a Dask LocalCluster of worker processes, and a worker killed mid-task."""
import json
import os
import sys

import numpy as np
import pytest

from conftest import model
from velocity.jobs import load_job
from velocity.progress import Progress
from velocity.png import decode_png

distributed = pytest.importorskip("distributed")  # a Debian dependency: scripts/deps.sh installs it


@pytest.fixture(scope="module")
def client():
    # Workers import this folder's helpers (the killing task) and the package.
    here = os.path.dirname(os.path.abspath(__file__))
    os.environ["PYTHONPATH"] = os.pathsep.join([here, os.environ.get("PYTHONPATH", "")])
    sys.path.insert(0, here)
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                       silence_logs=50)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def make_job(tmp_path, **kw):
    bad = tmp_path / "broken.ply"
    bad.write_text("ply\nformat ascii 1.0\nelement vertex 2\nend_header\n0 0 0\n")
    spec = {"models": [model("duck.asc"), model("fork.asc"), model("wuson_x4.obj"), str(bad)], "size": [40, 30],
            "views": {"type": "orbit", "count": 6}, "outputs": ["color", "depth", "mask"], "chunk": 3}
    spec.update(kw)
    p = tmp_path / "job.json"
    p.write_text(json.dumps(spec))
    return str(p)


def all_files(root):
    return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs)


def test_dask_runs_the_job_like_the_local_runner(tmp_path, client):
    from velocity.batch import run_local
    from velocity.dask_runner import run_dask
    path = make_job(tmp_path)
    m_dask = run_dask(load_job(path, str(tmp_path / "dask")), client=client, progress=Progress(False))
    m_local = run_local(load_job(path, str(tmp_path / "local")), progress=Progress(False))
    assert m_dask["views_done"] == m_local["views_done"] == 18
    assert m_dask["models_failed"] == ["broken"] and "broken.ply" in m_dask["models"]["broken"]["errors"][0]
    workers = {json.loads(open(tmp_path / "dask" / ".velocity" / "tasks" / f).read())["worker"]
               for f in os.listdir(tmp_path / "dask" / ".velocity" / "tasks")}
    assert len(workers) == 2  # both worker processes did tasks
    outputs = [f for f in all_files(tmp_path / "local") if not f.startswith(".velocity") and f != "manifest.json"]
    assert outputs == [f for f in all_files(tmp_path / "dask") if not f.startswith(".velocity") and f != "manifest.json"]
    for f in outputs:
        assert (tmp_path / "local" / f).read_bytes() == (tmp_path / "dask" / f).read_bytes(), f


def test_records_come_from_the_workers_when_the_folder_does_not_show_them(tmp_path, client, monkeypatch):
    # The client reads a finished task's record from the shared folder; where the folder
    # does not show it yet (another machine's rename not visible), it fetches the result.
    import velocity.dask_runner as dr
    monkeypatch.setattr(dr, "_finished_record", lambda job, task: None)
    path = make_job(tmp_path)
    fetched = dr.run_dask(load_job(path, str(tmp_path / "fetched")), client=client, progress=Progress(False))
    monkeypatch.undo()
    read = dr.run_dask(load_job(path, str(tmp_path / "read")), client=client, progress=Progress(False))
    for m in (fetched, read):
        assert m["views_done"] == 18 and m["models_failed"] == ["broken"]
    assert fetched["models"]["duck"]["views"] == read["models"]["duck"]["views"]


def test_the_cluster_keeps_glibc_heap_for_a_views_arrays(monkeypatch):
    # A nanny's default MALLOC_TRIM_THRESHOLD_=65536 made every array of a view an mmap
    # (13% more CPU per view); velocity's LocalCluster sets larger thresholds. (The
    # environment wins over Dask's setting, and the other tests' nannies put Dask's
    # default into this process's environment.)
    from velocity.dask_runner import local_cluster
    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
    monkeypatch.delenv("MALLOC_MMAP_THRESHOLD_", raising=False)
    cluster = local_cluster(1, silence_logs=50)
    with cluster, distributed.Client(cluster) as c:
        env = c.run(lambda: {k: os.environ.get(k) for k in ("MALLOC_TRIM_THRESHOLD_", "MALLOC_MMAP_THRESHOLD_")})
    assert list(env.values()) == [{"MALLOC_TRIM_THRESHOLD_": "134217728", "MALLOC_MMAP_THRESHOLD_": "33554432"}]


def test_a_worker_killed_mid_task_loses_nothing(tmp_path, client):
    from dask_helpers import killed_once_marker, run_task_dying_once
    from velocity.dask_runner import run_dask
    job = load_job(make_job(tmp_path, chunk=6, models=[model("duck.asc"), model("fork.asc")]), str(tmp_path / "out"))
    manifest = run_dask(job, client=client, progress=Progress(False), task_fn=run_task_dying_once)
    killed_pid, killed_task = open(killed_once_marker(job)).read().split()
    # The job completed: every view of every model, the killed task included.
    assert manifest["complete"] and manifest["views_done"] == 12 and not manifest["models_failed"]
    record = json.loads(open(job.record_path(killed_task)).read())
    assert record["status"] == "done" and not record["worker"].endswith(":" + killed_pid)  # ran again elsewhere
    # No partial file anywhere: the half-written one was never renamed into place and
    # the temporary folder is empty; every output decodes.
    out = tmp_path / "out"
    assert os.listdir(out / ".velocity" / "tmp") == []
    outputs = [f for f in all_files(out) if not f.startswith(".velocity") and f != "manifest.json"]
    assert len(outputs) == 12 * 3
    for f in outputs:
        if f.endswith(".png"):
            assert decode_png((out / f).read_bytes()).shape[:2] == (30, 40)
        else:
            assert np.load(out / f).shape == (30, 40)
    print(f"[dask] worker pid {killed_pid} killed in task {killed_task} at view 3; "
          f"the task ran again on {record['worker']} and the job completed with {manifest['views_done']} views")


def test_command_line_local_cluster(tmp_path):
    import subprocess
    path = make_job(tmp_path, models=[model("fork.asc")], output="out")
    p = subprocess.run([sys.executable, "-m", "velocity.batch", path, "--local-cluster", "2"], capture_output=True,
                       text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text())
    assert manifest["complete"] and manifest["views_done"] == 6
