"""Progress of long calls: `progress=` takes None/False (silent), True (a tqdm bar when
tqdm is installed, else one line per stage on stderr) or a callable
progress(done, total, stage) called after each stage."""
from __future__ import annotations

import sys
from typing import Any, Callable, Union

ProgressArg = Union[None, bool, Callable[[int, int, str], Any]]


class Progress:
    """Counts the stages of one call and reports each as it ends."""

    def __init__(self, progress: ProgressArg, label: str, total: int) -> None:
        self.label, self.total, self.done = label, total, 0
        self._call: Callable[[int, int, str], Any] | None = None
        self._bar = None
        if callable(progress):
            self._call = progress
        elif progress:
            try:
                from tqdm import tqdm
                self._bar = tqdm(total=total, desc=label, leave=False)
            except ImportError:
                self._call = lambda done, total, stage: print(f"{label}: {done}/{total} {stage}", file=sys.stderr)
        elif progress is not None and progress is not False:
            raise ValueError(f"progress must be None, a bool or a callable, got {progress!r}")

    def step(self, stage: str) -> None:
        self.done += 1
        if self._bar is not None:
            self._bar.set_postfix_str(stage)
            self._bar.update(1)
        if self._call is not None:
            self._call(self.done, self.total, stage)

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc: Any) -> None:
        if self._bar is not None:
            self._bar.close()
