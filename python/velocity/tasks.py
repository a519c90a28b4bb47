"""A job cut into tasks: each task is views [start, stop) of one model (a model's
views in one task, or chunks of `chunk` views), with the hash of everything its output
depends on (the model file's size and time, its views, the job's settings). A task that
runs again with the same hash may keep the files an earlier run wrote."""
from __future__ import annotations

import dataclasses
import hashlib
import json
import os

from .jobs import APPEARANCE, Job


@dataclasses.dataclass(frozen=True)
class Task:
    """One unit of work: views [start, stop) of one model."""
    id: str
    model: str
    model_key: str
    start: int
    stop: int
    hash: str


def plan_tasks(job: Job) -> list[Task]:
    """The job's tasks, model by model in the job's order, views in order."""
    n, chunk = job.view_count(), job.spec["chunk"] or job.view_count()
    # What changes the files: not the backend (both draw the same picture, to rounding),
    # nor an appearance option left at its default (so jobs from before they existed resume).
    settings = json.dumps({k: job.spec[k] for k in sorted(job.spec) if k not in ("models", "output", "chunk", "backend")
                           and not (k in APPEARANCE and job.spec[k] == APPEARANCE[k])}, sort_keys=True)
    out = []
    for key, path in job.models:
        try:
            st = os.stat(path)
            stamp = f"{st.st_size}:{st.st_mtime_ns}"
        except OSError:
            stamp = "missing"
        for start in range(0, n, chunk):
            stop = min(n, start + chunk)
            h = hashlib.sha1(f"{path}\n{stamp}\n{start}:{stop}\n{settings}".encode("utf-8", "surrogateescape")).hexdigest()
            tid = key if chunk >= n else f"{key}.{start:06d}-{stop:06d}"
            out.append(Task(tid, path, key, start, stop, h))
    return out
