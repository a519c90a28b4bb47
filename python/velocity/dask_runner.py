"""The batch job on a Dask cluster (Debian's python3-distributed): one Dask task per
Velocity task (a model, or a chunk of its views), run by the workers, which write to
the output folder on storage they all share, with the same atomic writes and task
records as the local runner (velocity.atomic, velocity.records). Dask schedules; there is no scheduler here.

A worker that dies in the middle of a task loses nothing: the scheduler runs the task
again on another worker (up to distributed.scheduler.allowed-failures times), the new
run skips the views already written, and files half-written by the dead worker sit in
<out>/.velocity/tmp until the run ends, when they are removed; a file at its final
name is always whole.

    dask scheduler                                   # on one machine
    dask worker tcp://scheduler:8786 --nworkers 2 --nthreads 1   # on each machine
    velocity-batch job.json --out /shared/renders --dask tcp://scheduler:8786
"""
from __future__ import annotations

import os
from typing import Any

from .atomic import write_json
from .jobs import Job
from .progress import Progress
from .records import read_record, task_record
from .render_task import run_task
from .run import Run
from .tasks import Task


# Dask settings for rendering tasks (each one a few hundred milliseconds or more). Dask's
# defaults suit many tiny tasks and cost a small cluster's cores: each worker's
# statistical profiler samples every 10 ms, and the event loops tick every 20 ms. Idle,
# a LocalCluster of 2 workers used 0.12 CPU-seconds a second with the defaults and
# 0.016 with these; that is 6% of a 2-core machine that renders instead. run_dask uses
# them for the LocalCluster it starts; for `dask scheduler` and `dask worker` on other
# machines, the same as environment variables (docs/python.md):
#   DASK_DISTRIBUTED__WORKER__PROFILE__ENABLED=False DASK_DISTRIBUTED__ADMIN__TICK__INTERVAL=1s ...
#
# And memory: a nanny starts its worker with MALLOC_TRIM_THRESHOLD_=65536, so that
# glibc hands freed memory back at once. Setting it also fixes glibc's mmap threshold
# at 128 KiB, so every image and depth array of a view (256x256: 196 and 256 KiB) is a
# fresh mmap and munmap, page faults and all: measured, a worker then spends 13% more
# CPU on the same views than a process without it. Here glibc keeps up to 32 MiB
# blocks in its heap and trims past 128 MiB free; with `dask worker`, export the same
# two variables (the environment wins over Dask's setting).
_NANNY_ENVIRON = {"MALLOC_TRIM_THRESHOLD_": 134217728, "MALLOC_MMAP_THRESHOLD_": 33554432,
                  "OMP_NUM_THREADS": 1, "MKL_NUM_THREADS": 1, "OPENBLAS_NUM_THREADS": 1}
DASK_CONFIG = {
    "distributed.nanny.pre-spawn-environ": _NANNY_ENVIRON,
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.worker.memory.monitor-interval": "1s",
    "distributed.scheduler.work-stealing-interval": "500ms",
}


def _task_on_worker(job: Job, task: Task, threads: int) -> dict:
    return run_task(job, task, threads)


def local_cluster(workers: int, **kwargs: Any) -> Any:
    """A Dask LocalCluster of `workers` processes of one thread each, with DASK_CONFIG
    (its workers inherit it from their nannies). `kwargs` go to LocalCluster."""
    import dask
    from distributed import LocalCluster
    with dask.config.set(DASK_CONFIG):
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                            **kwargs)


def _finished_record(job: Job, task: Task) -> dict | None:
    """The record a finished task left in the output folder, if it is this task's final one."""
    record = read_record(job, task.id)
    if record and record.get("hash") == task.hash and record.get("status") in ("done", "failed"):
        return record
    return None


def run_dask(job: Job, address: str | None = None, local_workers: int | None = None, client: Any = None,
             threads: int = 1, progress: Progress | None = None, task_fn: Any = None) -> dict:
    """Runs the job on the Dask cluster at `address`, on a LocalCluster of
    `local_workers` processes started here, or through an existing `client`. The output
    folder must be reachable at the same path by every worker. `threads` is the cores
    one frame may use on a worker (1: a worker process renders on one core; start
    workers with --nthreads 1 and one process per core). `task_fn(job, task, threads)`
    replaces the function run on the workers (it must be importable there; for
    instrumenting, as the killed-worker test does). Returns the manifest."""
    from distributed import Client, as_completed

    own_cluster = own_client = None
    if client is None:
        if address:
            client = own_client = Client(address)
        else:
            own_cluster = local_cluster(local_workers or os.cpu_count() or 1)
            client = own_client = Client(own_cluster)
    try:
        with Run(job, progress) as run:
            # One graph for every task (one submit each costs the client milliseconds,
            # which a small cluster's cores would otherwise spend on rendering). A key
            # of its own per task and content, so that a resubmitted job never picks up
            # a stale result from the scheduler's memory.
            n = len(run.todo)
            keys = [f"velocity-{task.id}-{task.hash[:12]}" for task in run.todo]
            submitted = client.map(task_fn or _task_on_worker, [job] * n, run.todo, [threads] * n, key=keys,
                                   pure=False, retries=0) if n else []
            futures = dict(zip(submitted, run.todo))
            for f in as_completed(futures):
                task = futures[f]
                # The worker wrote the task's record to the shared output folder before
                # it finished: read it there rather than fetch the result from the
                # worker (a round trip through the scheduler and the worker for each
                # task, CPU taken from a small cluster's rendering). Fetched only when
                # the file does not show it yet (a file system slow to show another
                # machine's rename, say).
                record = _finished_record(job, task) if f.status == "finished" else None
                if record is None:
                    try:
                        record = f.result()
                    except Exception as e:  # the task's workers kept dying (KilledWorker), or Dask failed
                        record = task_record(task, "failed", error=f"{type(e).__name__}: {e}")
                        write_json(job, job.record_path(task.id), record)
                run.finished(record)
                f.release()
        return run.manifest
    finally:
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()
