"""What is done: each task's record (<out>/.velocity/tasks/<task>.json), written by
whoever ran the task, and the manifest (<out>/manifest.json) made from them.

A task's record says "running" (with the hash of everything its output depends on)
while it works, then "done" or "failed"; a task that runs again with the same hash
skips the views whose files all exist, so a killed task resumes where it stopped. No
two processes ever write the same record or file except a task run twice, which writes
the same bytes."""
from __future__ import annotations

import json
import os
from typing import Any

from .jobs import JOB_VERSION, Job
from .tasks import Task


def task_record(task: Task, status: str, **fields: Any) -> dict[str, Any]:
    """A task's record: which task, model and views, the hash its output depends on,
    its status ("running", "done", "failed", or "interrupted" by a full disk), and `fields`."""
    return {"task": task.id, "model": task.model, "model_key": task.model_key, "hash": task.hash,
            "views": [task.start, task.stop], "status": status, **fields}


def read_record(job: Job, task_id: str) -> dict | None:
    try:
        with open(job.record_path(task_id), encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def is_done(job: Job, task: Task, record: dict | None) -> bool:
    """Whether `record` says this task (same hash) is done and every file of its views exists."""
    return record is not None and record.get("hash") == task.hash and record.get("status") == "done" and all(
        os.path.exists(p) for v in range(task.start, task.stop) for p in job.view_files(task.model_key, v).values())


def manifest(job: Job, tasks: list[Task], records: dict[str, dict]) -> dict:
    """The manifest of `job` from its `tasks` and the `records` of those finished (by
    task id): every model's status, errors, and each done view's cameras and files."""
    models: dict[str, Any] = {}
    total = done = 0
    for t in tasks:
        m = models.setdefault(t.model_key, {"model": t.model, "status": "pending", "views": {}, "errors": []})
        rec = records.get(t.id)
        total += t.stop - t.start
        if rec is None:
            continue
        if rec["status"] == "interrupted":
            m["interrupted"] = True  # a full disk stopped it: not the model's failure
            continue
        if rec["status"] == "done":
            done += t.stop - t.start
            for v, cam in rec.get("cameras", {}).items():
                m["views"][v] = dict(cam, files=job.view_names(t.model_key, int(v)))
        else:
            m["errors"].append(f"views {t.start}..{t.stop - 1}: {rec.get('error', 'unknown error')}")
    failed = []
    for key, m in models.items():
        parts = [r["status"] for t in tasks if t.model_key == key for r in [records.get(t.id)] if r]
        n_tasks = sum(1 for t in tasks if t.model_key == key)
        m["status"] = "failed" if "failed" in parts else "done" if parts.count("done") == n_tasks else "pending"
        if m["status"] == "failed":
            failed.append(key)
    return {"version": JOB_VERSION, "job": job.spec, "views_total": total, "views_done": done,
            "models_failed": failed, "complete": done == total, "models": models}
