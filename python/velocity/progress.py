"""The batch runner's progress bar: tqdm's (Debian's python3-tqdm), views done of the
total with the rate and the ETA, on a terminal (stderr); silent otherwise."""
from __future__ import annotations

from typing import Any


class Progress:
    """A progress bar with the rate and ETA on a terminal (stderr); silent otherwise."""

    def __init__(self, enabled: bool | None = None, stream: Any = None) -> None:
        import sys
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.failed = 0
        self._bar = None

    def start(self, total: int, already: int) -> None:
        if not self.enabled:
            return
        from tqdm import tqdm
        # Views already done count towards the bar, not towards the rate.
        self._bar = tqdm(total=total, initial=already, unit="view", file=self.stream, dynamic_ncols=True,
                         mininterval=0.1, smoothing=0.1, desc="velocity-batch")

    def advance(self, views: int, failed: bool = False) -> None:
        self.failed += views if failed else 0
        if self._bar is not None:
            if failed:
                self._bar.set_postfix_str(f"{self.failed} failed", refresh=False)
            self._bar.update(views)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None
