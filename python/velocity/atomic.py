"""Files in a job's output folder written whole or not at all: each is written to
<out>/.velocity/tmp and renamed into place (atomic on one file system), so a file that
exists is whole. Half-written files of a killed process stay in the tmp folder until the
next run sweeps it (velocity.run)."""
from __future__ import annotations

import json
import os
import threading
import time
import uuid
from typing import Any, Callable

from .jobs import Job

# In a worker process: the pid of the main process whose lock covers the folder, and
# this worker's parent. A file is renamed into place only while both live, so that a
# worker never writes into the folder after the main process (and its lock) is gone.
_owner: tuple[int, int] | None = None


def set_owner(pid: int) -> None:
    """Makes this worker stop when process `pid` (the job's main process) is gone: it
    is checked before each file is put in place, and every 0.2 s by a watcher thread
    (a worker busy rendering, or idle, stops too)."""
    global _owner
    _owner = (pid, os.getppid())

    def watch() -> None:
        while True:
            _check_owner()
            time.sleep(0.2)

    threading.Thread(target=watch, name="velocity-owner-watch", daemon=True).start()


def _check_owner() -> None:
    if _owner is None:
        return
    pid, parent = _owner
    try:
        os.kill(pid, 0)
        alive = os.getppid() == parent
    except ProcessLookupError:
        alive = False
    except PermissionError:
        alive = True
    if not alive:
        os._exit(1)  # the job's main process is gone: stop at once, write nothing more


def atomic_write(job: Job, path: str, write: Callable[[Any], None]) -> None:
    """Writes a file whole or not at all: `write(f)` fills a temporary file in the job's
    tmp folder (same file system), which then replaces `path` in one rename."""
    os.makedirs(job.tmp_dir, exist_ok=True)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = os.path.join(job.tmp_dir, f"{uuid.uuid4().hex}.{os.path.basename(path)}")
    try:
        with open(tmp, "wb") as f:
            write(f)
        _check_owner()
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_json(job: Job, path: str, data: Any) -> None:
    # Compact: the json module's C encoder runs only without indent (10x faster).
    atomic_write(job, path, lambda f: f.write(json.dumps(data, sort_keys=True, separators=(",", ":")).encode()))
