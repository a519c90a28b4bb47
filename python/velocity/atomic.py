"""Files in a job's output folder written whole or not at all: each is written to
<out>/.velocity/tmp and renamed into place (atomic on one file system), so a file that
exists is whole. Half-written files of a killed process stay in the tmp folder until the
next run sweeps it (velocity.run)."""
from __future__ import annotations

import json
import os
import uuid
from typing import Any, Callable

from .jobs import Job


def atomic_write(job: Job, path: str, write: Callable[[Any], None]) -> None:
    """Writes a file whole or not at all: `write(f)` fills a temporary file in the job's
    tmp folder (same file system), which then replaces `path` in one rename."""
    os.makedirs(job.tmp_dir, exist_ok=True)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = os.path.join(job.tmp_dir, f"{uuid.uuid4().hex}.{os.path.basename(path)}")
    try:
        with open(tmp, "wb") as f:
            write(f)
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
