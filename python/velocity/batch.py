"""velocity-batch (also `python3 -m velocity.batch`): render a job of many models x many
views to an output folder, on this machine or on a Dask cluster.

    velocity-batch job.json --out renders                 one process, every core
    velocity-batch job.json --out renders --workers 2     two processes, one core each
    velocity-batch job.json --dask tcp://scheduler:8786   on a Dask cluster
    velocity-batch job.json --local-cluster 4             on a Dask LocalCluster here

A progress bar with an ETA is drawn on a terminal; nothing when output is not one.
Run it again to resume: done work is skipped. Exit status: 0 when every view is done,
3 when some models failed (listed in <out>/manifest.json), 1 for a job that cannot run,
2 for bad arguments. The job format and the output folder: velocity.jobs, docs/python.md.
"""
from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import threading
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from typing import Any

from .jobs import APPEARANCE, BACKENDS, Job, JobError, load_job
from .progress import Progress
from .render_task import run_task
from .run import Run


def _mp_context():
    """forkserver where the platform has it: the server imports numpy and the engine
    once, and each worker is a fork of it, ready at once; a fork of a server that has
    started no renderer, so no engine thread is copied half-way. spawn elsewhere."""
    import multiprocessing
    if "forkserver" in multiprocessing.get_all_start_methods():
        ctx = multiprocessing.get_context("forkserver")
        ctx.set_forkserver_preload(["numpy", "velocity", "velocity.render_task", "velocity.png"])
        return ctx
    return multiprocessing.get_context("spawn")


def _worker_started(barrier: Any, owner: int) -> None:
    import velocity  # noqa: F401  (already there under forkserver)
    from . import atomic
    _die_with_parent()
    atomic.set_owner(owner)
    barrier.wait()


def _die_with_parent() -> None:
    """This worker is killed when its parent (the forkserver, which exits as soon as the
    main process is gone, however it went) dies: Linux's parent-death signal."""
    parent = os.getppid()
    try:
        import ctypes
        libc = ctypes.CDLL(None, use_errno=True)
        PR_SET_PDEATHSIG = 1
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        pass  # not Linux: atomic.set_owner's check before each file still holds
    if os.getppid() != parent:  # the parent died before the signal was set
        os._exit(1)


def _no_op() -> None:
    pass


class LocalPool:
    """Worker processes on this machine, started once and given any number of jobs, as
    a Dask cluster is. Each renders one task at a time; `threads` is the cores one frame
    may use in a worker (1: one core per worker, as many workers as cores).

        with LocalPool(2) as pool:
            run_local(job_a, pool=pool)
            run_local(job_b, pool=pool)

    The constructor returns once every worker has started and imported the engine, so
    that a job's time is the job's alone."""

    def __init__(self, workers: int, threads: int = 1, start_timeout: float = 120.0) -> None:
        if workers < 1:
            raise JobError(f"LocalPool: workers must be at least 1, got {workers}")
        self.workers, self.threads = workers, threads
        ctx = _mp_context()
        barrier = ctx.Barrier(workers + 1)
        self._executor = ProcessPoolExecutor(workers, mp_context=ctx, initializer=_worker_started,
                                             initargs=(barrier, os.getpid()))
        try:
            # The executor starts a worker per task submitted while none is idle.
            for _ in range(workers):
                self._executor.submit(_no_op)
            barrier.wait(start_timeout)
        except BaseException as e:
            self._executor.shutdown(wait=False, cancel_futures=True)
            if isinstance(e, threading.BrokenBarrierError):
                raise JobError(f"the {workers} worker processes did not start within {start_timeout:.0f} s") from None
            raise

    def run(self, job: Job, progress: Progress | None = None, force: bool = False) -> dict:
        """Runs the job on the pool's workers; returns the manifest."""
        with Run(job, progress, force) as run:
            futures = {self._executor.submit(run_task, job, task, self.threads): task for task in run.todo}
            try:
                for f in as_completed(futures):
                    run.finished(f.result())
                    if run.disk_full:  # the rest would fail too: stop, keep what is done
                        for other in futures:
                            other.cancel()
            except BrokenProcessPool:
                # A process was killed (out of memory, say). What it finished is
                # recorded; a second run resumes the rest.
                raise JobError("a worker process died; run the job again to resume it") from None
        if run.disk_full:
            raise JobError(run.stop_message())
        return run.manifest

    def close(self) -> None:
        self._executor.shutdown(wait=True, cancel_futures=True)

    def __enter__(self) -> "LocalPool":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def run_local(job: Job, workers: int = 1, threads: int | None = None, progress: Progress | None = None,
              hooks: dict | None = None, pool: LocalPool | None = None, force: bool = False) -> dict:
    """Runs the job here: on `pool`'s workers when one is given, else in this process
    (workers=1) or in a LocalPool of `workers` processes started for this job. `threads`
    is the cores one frame may use (default: every core for one worker, 1 each for
    several; a pool has its own). `hooks` (in-process only) are for tests. Returns the
    manifest."""
    if pool is not None:
        return pool.run(job, progress, force)
    if workers < 1:
        raise JobError(f"--workers must be at least 1, got {workers}")
    if threads is None:
        threads = 0 if workers == 1 else 1
    if workers > 1:
        with LocalPool(workers, threads) as own:
            return own.run(job, progress, force)
    with Run(job, progress, force) as run:
        for task in run.todo:
            run.finished(run_task(job, task, threads, hooks))
            if run.disk_full:
                break
    if run.disk_full:
        raise JobError(run.stop_message())
    return run.manifest


def _summary(manifest: dict, out: str) -> str:
    failed = manifest["models_failed"]
    text = f"velocity-batch: {manifest['views_done']}/{manifest['views_total']} views done in {out}"
    if failed:
        text += f"; {len(failed)} model(s) failed: {', '.join(failed[:5])}{' ...' if len(failed) > 5 else ''}" \
                f" (errors in {os.path.join(out, 'manifest.json')})"
    return text


def _check_backend(backend: str) -> None:
    """A backend the workers cannot start is the job's error, said once, before any task
    (in a child process: an OpenGL context is not carried across the workers' fork)."""
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    probe = (f"import sys; sys.path.insert(0, {package_parent!r}); import velocity; "
             f"velocity.OffscreenRenderer(8, 8, backend={backend!r})")
    run = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True)
    if run.returncode != 0:
        lines = run.stderr.strip().splitlines()
        raise JobError(f"backend {backend}: {lines[-1].split(': ', 1)[-1] if lines else 'cannot start'}")


def main(argv: list[str] | None = None) -> int:
    # `velocity batch` (the C++ program) runs this module and names itself so.
    p = argparse.ArgumentParser(prog=os.environ.get("VELOCITY_BATCH_PROG", "velocity-batch"), description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="The job format: docs/python.md (Batch jobs).")
    p.add_argument("job", help="the job file (JSON)")
    p.add_argument("--out", help="output folder (default: the job's \"output\")")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, default=1, help="processes on this machine (default 1)")
    where.add_argument("--dask", metavar="ADDRESS", help="a Dask scheduler's address, e.g. tcp://host:8786")
    where.add_argument("--local-cluster", type=int, metavar="N", help="start a Dask LocalCluster of N worker processes")
    p.add_argument("--threads", type=int, default=None,
                   help="cores one frame may use (default: all with one worker, else 1)")
    p.add_argument("--progress", choices=("auto", "always", "never"), default="auto",
                   help="progress bar: on a terminal (auto), always or never")
    p.add_argument("--force", action="store_true",
                   help="write into a folder that holds another job's renders (they are removed first)")
    look = p.add_argument_group("renderer (each overrides the job's key of the same name)")
    look.add_argument("--backend", choices=BACKENDS, help="cpu, gpu (OpenGL 3.3 through EGL) or auto")
    look.add_argument("--color", choices=("auto", "linear", "display"), help="colour pipeline")
    look.add_argument("--tone-map", dest="tone_map", choices=("none", "aces", "neutral"), help="tone mapping")
    look.add_argument("--exposure", type=float, help="linear light is multiplied by this (>= 0)")
    look.add_argument("--shadows", action=argparse.BooleanOptionalAction, help="shadow maps for every light")
    look.add_argument("--shadow-map-size", dest="shadow_map_size", type=int, help="texels a side, 16..8192")
    look.add_argument("--point-size", dest="point_size", type=float, help="a point's side in pixels, 1..64")
    args = p.parse_args(argv)
    if args.threads is not None and args.threads < 0:
        p.error("--threads must be >= 0")
    progress = Progress(None if args.progress == "auto" else args.progress == "always")
    try:
        overrides = {k: getattr(args, k) for k in ("backend", *APPEARANCE) if getattr(args, k) is not None}
        job = load_job(args.job, args.out, overrides)
        if job.spec["backend"] != "cpu" and not (args.dask or args.local_cluster):
            _check_backend(job.spec["backend"])
        if args.dask or args.local_cluster:
            from .dask_runner import run_dask
            manifest = run_dask(job, address=args.dask, local_workers=args.local_cluster,
                                threads=1 if args.threads is None else args.threads, progress=progress)
        else:
            manifest = run_local(job, args.workers, args.threads, progress, force=args.force)
    except JobError as e:
        print(f"velocity-batch: {e}", file=sys.stderr)
        return 1
    except OSError as e:  # the output folder cannot be made or written: one line, no traceback
        from .render_task import disk_full
        where = os.fsdecode(e.filename) if e.filename else (args.out or args.job)
        if disk_full(e):
            print(f"velocity-batch: {where}: no space left on device after 0 views; free space and run again "
                  "to resume", file=sys.stderr)
        else:
            print(f"velocity-batch: {where}: {e.strerror or e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("velocity-batch: interrupted; run again to resume", file=sys.stderr)
        return 130
    if progress.enabled or manifest["models_failed"]:
        print(_summary(manifest, job.output), file=sys.stderr)
    return 3 if manifest["models_failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
