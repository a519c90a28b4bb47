"""The batch runner's progress bar: views done of the total, the rate and the ETA, on a
terminal (stderr); silent otherwise."""
from __future__ import annotations

import time
from typing import Any


class Progress:
    """A progress bar with the rate and ETA on a terminal (stderr); silent otherwise."""

    def __init__(self, enabled: bool | None = None, stream: Any = None) -> None:
        import sys
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.total = self.done = self.skipped = self.failed = 0
        self.t0 = time.time()
        self._last = 0.0

    def start(self, total: int, already: int) -> None:
        self.total, self.done, self.skipped, self.t0 = total, already, already, time.time()
        self._draw(force=True)

    def advance(self, views: int, failed: bool = False) -> None:
        self.done += views
        self.failed += views if failed else 0
        self._draw()

    def _draw(self, force: bool = False) -> None:
        if not self.enabled or (not force and time.time() - self._last < 0.1 and self.done < self.total):
            return
        self._last = time.time()
        new, elapsed = self.done - self.skipped, time.time() - self.t0
        rate = new / elapsed if elapsed > 0 else 0.0
        left = self.total - self.done
        eta = f"{int(left / rate) // 60}:{int(left / rate) % 60:02d}" if rate > 0 else "?"
        width = 30
        filled = int(width * self.done / self.total) if self.total else width
        fail = f"  {self.failed} failed" if self.failed else ""
        self.stream.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} views"
                          f"  {rate:.1f}/s  ETA {eta}{fail} ")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self._draw(force=True)
            self.stream.write("\n")
            self.stream.flush()
