"""velocity-batch against the faults a dataset job meets: hostile job files, globs and
names, a folder used by another job, a full disk, and its main process killed."""
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

from conftest import SANITIZER, model

BATCH = [sys.executable, "-m", "velocity.batch"]


def batch(*args, timeout=120, **kw):
    """Runs velocity-batch; returns (exit status, stderr)."""
    p = subprocess.run(BATCH + [os.fspath(a) for a in args], capture_output=True, timeout=timeout, **kw)
    return p.returncode, p.stderr.decode("utf-8", "replace")


def one_line(err):
    assert "Traceback" not in err, err
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("velocity-batch: "), err
    return lines[0]


def write_job(folder, **spec):
    spec.setdefault("size", [24, 18])
    spec.setdefault("views", {"type": "orbit", "count": 2, "elevation_deg": 20})
    spec.setdefault("outputs", ["color", "depth"])
    path = folder / "job.json"
    path.write_text(json.dumps(spec))
    return path


def test_job_files_that_are_not_files_or_too_big(tmp_path):
    code, err = batch("/dev/zero", "--out", tmp_path / "out", timeout=60)
    assert code == 1 and "not a regular file" in one_line(err)
    fifo = tmp_path / "job.fifo"
    os.mkfifo(fifo)
    code, err = batch(fifo, "--out", tmp_path / "out", timeout=60)  # nobody writes it: must not wait
    assert code == 1 and "not a regular file" in one_line(err)
    big = tmp_path / "big.json"
    with open(big, "wb") as f:
        f.truncate(64 << 20)  # sparse: 64 MiB of zeros
    code, err = batch(big, "--out", tmp_path / "out")
    assert code == 1 and "at most" in one_line(err)
    (tmp_path / "latin1.json").write_bytes(b'{"models": ["\xe9.asc"]}')
    code, err = batch(tmp_path / "latin1.json", "--out", tmp_path / "out")
    assert code == 1 and "not UTF-8" in one_line(err)
    (tmp_path / "deep.json").write_text("[" * 100000)
    code, err = batch(tmp_path / "deep.json", "--out", tmp_path / "out")
    assert code == 1 and one_line(err)
    code, err = batch(tmp_path / "missing.json")
    assert code == 1 and "cannot read" in one_line(err)


def test_globs_stay_in_the_job_folder_and_skip_special_files(tmp_path):
    for pattern in ("/proc/**", "../**/*.asc", "/etc/*"):
        job = write_job(tmp_path, models=[pattern], output="out")
        started = time.monotonic()
        code, err = batch(job, timeout=60)
        assert code == 1 and "leaves the job file's folder" in one_line(err), pattern
        assert time.monotonic() - started < 30
    meshes = tmp_path / "meshes"
    (meshes / "sub").mkdir(parents=True)
    shutil.copy(model("duck.asc"), meshes / "sub" / "duck.asc")
    os.mkfifo(meshes / "pipe.asc")                      # a special file: skipped
    outside = tmp_path.parent / (tmp_path.name + "-outside")
    outside.mkdir()
    shutil.copy(model("fork.asc"), outside / "fork.asc")
    os.symlink(outside, meshes / "link")                # a link out of the tree: not followed
    os.symlink(outside / "fork.asc", meshes / "fork.asc")  # a file reached through a link out: skipped
    os.symlink(meshes, meshes / "sub" / "loop")         # a loop: walked once
    job = write_job(tmp_path, models=["meshes/**/*.asc"], output="out")
    code, err = batch(job, timeout=120)
    assert code == 0, err
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text())
    assert sorted(manifest["models"]) == ["duck"] and manifest["complete"]


def test_output_is_contained_unless_given_on_the_command_line(tmp_path):
    for out in ("/tmp/velocity-elsewhere", "../elsewhere"):
        job = write_job(tmp_path, models=[model("duck.asc")], output=out)
        code, err = batch(job)
        assert code == 1 and "outside the job file's folder" in one_line(err)
    code, err = batch(job, "--out", tmp_path / "chosen")
    assert code == 0 and (tmp_path / "chosen" / "manifest.json").exists()


def test_non_utf8_file_names_are_rendered(tmp_path):
    folder = os.fsencode(str(tmp_path))
    shutil.copy(model("duck.asc"), os.path.join(folder, b"\xe9nte.asc"))
    shutil.copy(model("fork.asc"), os.path.join(folder, b"fork.asc"))
    job = write_job(tmp_path, models=["*.asc"], output="out")
    code, err = batch(job)
    assert code == 0, err
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text())
    assert manifest["complete"] and manifest["views_done"] == 4 and len(manifest["models"]) == 2


def test_a_different_job_in_a_used_folder_is_refused_unless_forced(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    job_a = write_job(tmp_path / "a", models=[model("duck.asc")])
    job_b = write_job(tmp_path / "b", models=[model("fork.asc")])
    out = tmp_path / "out"
    assert batch(job_a, "--out", out)[0] == 0
    assert batch(job_a, "--out", out)[0] == 0  # the same job again: resumes
    code, err = batch(job_b, "--out", out)
    assert code == 1 and "another job" in one_line(err) and "--force" in err
    assert (out / "duck").is_dir()
    code, err = batch(job_b, "--out", out, "--force")
    assert code == 0, err
    assert not (out / "duck").exists() and (out / "fork").is_dir()  # never mixed
    manifest = json.loads((out / "manifest.json").read_text())
    assert list(manifest["models"]) == ["fork"]
    stranger = tmp_path / "stranger"
    stranger.mkdir()
    (stranger / "thesis.tex").write_text("mine")
    code, err = batch(job_a, "--out", stranger)
    assert code == 1 and "not empty" in one_line(err) and (stranger / "thesis.tex").exists()


def test_views_per_job_are_bounded(tmp_path):
    job = write_job(tmp_path, models=[model("duck.asc")] * 1 + [model("fork.asc")],
                    views={"type": "orbit", "count": 1_000_000, "elevation_deg": [0, 10, 20, 30, 40, 50]},
                    output="out")
    code, err = batch(job)
    assert code == 1 and "at most 10000000" in one_line(err)


def can_mount_tmpfs():
    if not shutil.which("unshare"):
        return False
    return subprocess.run(["unshare", "--user", "--map-root-user", "--mount", "sh", "-c",
                           "mount -t tmpfs -o size=64k tmpfs /mnt"], capture_output=True).returncode == 0


@pytest.mark.skipif(not can_mount_tmpfs(), reason="cannot mount a tmpfs here (no user namespaces)")
def test_full_disk_stops_the_job_with_one_line_and_a_true_manifest(tmp_path):
    # A real full disk: the job's output on a 400 KiB tmpfs, mounted in a user namespace.
    job = write_job(tmp_path, models=[model("duck.asc"), model("fork.asc")], size=[160, 120],
                    views={"type": "orbit", "count": 12, "elevation_deg": 20}, outputs=["color", "depth"],
                    chunk=4)
    mnt = tmp_path / "mnt"
    mnt.mkdir()
    env = dict(os.environ)
    script = (f"mount -t tmpfs -o size=400k tmpfs {mnt} && "
              f"{sys.executable} -m velocity.batch {job} --out {mnt}/out; status=$?; "
              f"cp -r {mnt}/out {tmp_path}/copy; exit $status")
    p = subprocess.run(["unshare", "--user", "--map-root-user", "--mount", "sh", "-c", script],
                       capture_output=True, timeout=300, env=env)
    err = p.stderr.decode()
    line = one_line(err)
    assert p.returncode == 1
    prefix = f"velocity-batch: {mnt}/out: no space left on device after "
    assert line.startswith(prefix) and line.endswith(" views; free space and run again to resume"), line
    written = int(line[len(prefix):].split()[0])
    assert 0 < written < 24
    copy = tmp_path / "copy"
    records = [json.loads((copy / ".velocity" / "tasks" / n).read_text())
               for n in os.listdir(copy / ".velocity" / "tasks")]
    assert not any(r["status"] == "failed" for r in records)  # interrupted or running, never failed
    on_disk = sum(1 for d in ("duck", "fork") if (copy / d).is_dir() for n in os.listdir(copy / d)
                  if n.endswith(".depth.npy"))
    if (copy / "manifest.json").exists():  # a manifest, when there was room for one, is true
        manifest = json.loads((copy / "manifest.json").read_text())
        assert not manifest["complete"] and not manifest["models_failed"]
        assert manifest["views_done"] <= on_disk
    # Room again: the job resumes and finishes.
    code, err = batch(job, "--out", copy)
    assert code == 0, err
    assert json.loads((copy / "manifest.json").read_text())["complete"]


def session_processes(sid):
    """The pids of live processes in session `sid` (the batch and everything it started)."""
    pids = []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open(f"/proc/{name}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if fields[0] != "Z" and int(fields[3]) == sid:  # state, ppid, pgrp, session
            pids.append(int(name))
    return pids


def count_files(root):
    return sum(len(fs) for _, _, fs in os.walk(root))


@pytest.mark.skipif(SANITIZER != "", reason="kills processes under a sanitizer's runtime")
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGKILL])
def test_killing_the_main_process_stops_every_worker(tmp_path, sig):
    job = write_job(tmp_path, models=[model("duck.asc"), model("fork.asc")] * 1, size=[320, 240],
                    views={"type": "orbit", "count": 4000, "elevation_deg": 20}, chunk=5,
                    outputs=["color", "depth"], output="out")
    main = subprocess.Popen(BATCH + [str(job), "--workers", "2"], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    out = tmp_path / "out"
    deadline = time.monotonic() + 120
    while count_files(out) < 20 and time.monotonic() < deadline and main.poll() is None:
        time.sleep(0.05)
    assert main.poll() is None and count_files(out) >= 20, "the job did not get going"
    assert len(session_processes(main.pid)) >= 3  # main, forkserver, workers
    os.kill(main.pid, sig)  # the main process only, as systemd or the OOM killer do
    main.wait(timeout=30)
    deadline = time.monotonic() + 30
    while session_processes(main.pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert session_processes(main.pid) == [], "workers outlived the main process"
    # Nothing is written after that (the lock is gone with the main process).
    before = count_files(out)
    time.sleep(1.0)
    assert count_files(out) == before
