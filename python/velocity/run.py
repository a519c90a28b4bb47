"""One runner's pass over a job, shared by the local runner (velocity.batch) and the
Dask runner (velocity.dask_runner): the lock on the output folder, what is left to do,
progress, and the manifest written as tasks finish."""
from __future__ import annotations

import json
import os
import shutil
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

    def __init__(self, job: Job, progress: Progress | None = None, force: bool = False) -> None:
        self.job, self.progress, self.force = job, progress, force
        self.written = 0          # views this pass wrote
        self.disk_full = False    # a task stopped for want of space: the pass stops
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
        try:
            self._claim()
        except BaseException:
            self._lock_file.close()
            raise
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

    def _claim(self) -> None:
        """The folder is this job's: refuses one that holds another job's renders (or
        files of its own) unless forced, when the other job's files are removed first,
        so that two jobs' files are never mixed."""
        out, path = self.job.output, os.path.join(self.job.state_dir, "job.json")
        try:
            with open(path, encoding="utf-8") as f:
                owner = json.load(f)
        except (OSError, ValueError):
            owner = None
        keys = [k for k, _ in self.job.models]
        if owner is not None and owner.get("source") != self.job.source:
            if not self.force:
                raise JobError(f"{out}: holds the renders of another job ({owner.get('source', '?')[5:]}); "
                               "run with --force to replace them, or choose another --out")
            for key in owner.get("model_keys", []):
                folder = os.path.join(out, key)
                if os.path.dirname(os.path.abspath(folder)) == os.path.abspath(out) and os.path.isdir(folder):
                    shutil.rmtree(folder, ignore_errors=True)
            shutil.rmtree(os.path.join(self.job.state_dir, "tasks"), ignore_errors=True)
            os.makedirs(os.path.join(self.job.state_dir, "tasks"), exist_ok=True)
            for name in ("manifest.json",):
                try:
                    os.unlink(os.path.join(out, name))
                except OSError:
                    pass
        elif owner is None and not self.force:
            others = [n for n in os.listdir(out) if n != ".velocity"]
            if others and not os.path.exists(os.path.join(out, "manifest.json")):
                raise JobError(f"{out}: is not empty and holds no velocity batch output ({others[0]!r}, ...); "
                               "run with --force to write there anyway, or choose another --out")
        if owner is not None and owner.get("source") == self.job.source:
            keys = list(dict.fromkeys(owner.get("model_keys", []) + keys))
        write_json(self.job, path, {"source": self.job.source, "model_keys": keys})

    def finished(self, record: dict) -> None:
        self.records[record["task"]] = record
        self.written += record.get("written", 0)
        if record["status"] == "interrupted":
            self.disk_full = True
        if self.progress:
            a, b = record["views"]
            self.progress.advance(b - a, failed=record["status"] != "done")
        if time.time() - self._last_manifest > 2.0:
            try:
                self.write_manifest()
            except OSError as e:
                from .render_task import disk_full
                if not disk_full(e):
                    raise
                self.disk_full = True

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

    def stop_message(self) -> str:
        return (f"{self.job.output}: no space left on device after {self.written} views; "
                "free space and run again to resume")

    def __exit__(self, *exc: Any) -> None:
        try:
            self.manifest = self.write_manifest()
        except OSError as e:
            from .render_task import disk_full
            if not disk_full(e):
                raise
            # No room for a true manifest: none rather than a stale one (the next run
            # writes it from the tasks' records).
            self.disk_full = True
            self.manifest = manifest(self.job, self.tasks, self.records)
            try:
                os.unlink(os.path.join(self.job.output, "manifest.json"))
            except OSError:
                pass
        self._sweep()
        if self.progress:
            self.progress.close()
        if self._lock_file:
            self._lock_file.close()
