"""One runner's pass over a job, shared by the local runner (velocity.batch) and the
Dask runner (velocity.dask_runner): the lock on the output folder, what is left to do,
progress, and the manifest written as tasks finish."""
from __future__ import annotations

import os
import time
from typing import Any

from .atomic import write_json
from .jobs import Job, JobError
from .progress import Progress
from .records import is_done, manifest, read_record
from .tasks import plan_tasks


class Run:
    """One runner's pass over a job: the lock on the output folder, what is left to do,
    progress, and the manifest. Used by both runners:

        with Run(job) as run:
            for task in run.todo: ...; run.finished(record)
    """

    def __init__(self, job: Job, progress: Progress | None = None) -> None:
        self.job, self.progress = job, progress
        self.tasks = plan_tasks(job)
        self.records: dict[str, dict] = {}
        self._lock_file = None
        self._last_manifest = 0.0

    def __enter__(self) -> "Run":
        import fcntl
        os.makedirs(os.path.join(self.job.state_dir, "tasks"), exist_ok=True)
        self._lock_file = open(os.path.join(self.job.state_dir, "lock"), "w")
        try:
            fcntl.flock(self._lock_file, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            self._lock_file.close()
            raise JobError(f"{self.job.output}: another velocity batch run is using this folder") from None
        self._sweep()
        self.todo = []
        for t in self.tasks:
            rec = read_record(self.job, t.id)
            if is_done(self.job, t, rec):
                self.records[t.id] = rec
            else:
                self.todo.append(t)
        if self.progress:
            self.progress.start(sum(t.stop - t.start for t in self.tasks),
                                sum(t.stop - t.start for t in self.tasks if t.id in self.records))
        return self

    def finished(self, record: dict) -> None:
        self.records[record["task"]] = record
        if self.progress:
            a, b = record["views"]
            self.progress.advance(b - a, failed=record["status"] != "done")
        if time.time() - self._last_manifest > 2.0:
            self.write_manifest()

    def _sweep(self) -> None:
        """Removes half-written files left by killed processes (this run holds the lock)."""
        try:
            names = os.listdir(self.job.tmp_dir)
        except OSError:
            return
        for n in names:
            try:
                os.unlink(os.path.join(self.job.tmp_dir, n))
            except OSError:
                pass

    def write_manifest(self) -> dict:
        self._last_manifest = time.time()
        m = manifest(self.job, self.tasks, self.records)
        write_json(self.job, os.path.join(self.job.output, "manifest.json"), m)
        return m

    def __exit__(self, *exc: Any) -> None:
        self.manifest = self.write_manifest()
        self._sweep()
        if self.progress:
            self.progress.close()
        if self._lock_file:
            self._lock_file.close()
