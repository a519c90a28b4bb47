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
import sys
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from multiprocessing import get_context
from typing import Any

from .jobs import Job, JobError, Progress, Run, load_job, run_task


def run_local(job: Job, workers: int = 1, threads: int | None = None, progress: Progress | None = None,
              hooks: dict | None = None) -> dict:
    """Runs the job here: in this process (workers=1) or in `workers` processes started
    with multiprocessing ("spawn"), each rendering one task at a time. `threads` is the
    cores one frame may use (default: every core for one worker, 1 each for several).
    Returns the manifest."""
    if workers < 1:
        raise JobError(f"--workers must be at least 1, got {workers}")
    if threads is None:
        threads = 0 if workers == 1 else 1
    with Run(job, progress) as run:
        if workers == 1:
            for task in run.todo:
                run.finished(run_task(job, task, threads, hooks))
        else:
            with ProcessPoolExecutor(workers, mp_context=get_context("spawn")) as pool:
                futures = {pool.submit(run_task, job, task, threads): task for task in run.todo}
                try:
                    for f in as_completed(futures):
                        run.finished(f.result())
                except BrokenProcessPool:
                    # A process was killed (out of memory, say). What it finished is
                    # recorded; a second run resumes the rest.
                    raise JobError("a worker process died; run the job again to resume it") from None
    return run.manifest


def _summary(manifest: dict, out: str) -> str:
    failed = manifest["models_failed"]
    text = f"velocity-batch: {manifest['views_done']}/{manifest['views_total']} views done in {out}"
    if failed:
        text += f"; {len(failed)} model(s) failed: {', '.join(failed[:5])}{' ...' if len(failed) > 5 else ''}" \
                f" (errors in {os.path.join(out, 'manifest.json')})"
    return text


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
    args = p.parse_args(argv)
    if args.threads is not None and args.threads < 0:
        p.error("--threads must be >= 0")
    progress = Progress(None if args.progress == "auto" else args.progress == "always")
    try:
        job = load_job(args.job, args.out)
        if args.dask or args.local_cluster:
            from .dask_runner import run_dask
            manifest = run_dask(job, address=args.dask, local_workers=args.local_cluster,
                                threads=1 if args.threads is None else args.threads, progress=progress)
        else:
            manifest = run_local(job, args.workers, args.threads, progress)
    except JobError as e:
        print(f"velocity-batch: {e}", file=sys.stderr)
        return 1
    if progress.enabled or manifest["models_failed"]:
        print(_summary(manifest, job.output), file=sys.stderr)
    return 3 if manifest["models_failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
