"""Progress of long calls: `progress=` takes None/False (silent), True (a tqdm bar when
tqdm is installed, else one line per stage on stderr) or a callable
progress(done, total, stage). `Progress` counts the stages of a Python-side call
(dtlab.spatial); `StageBar` is handed to the C++ calls (tetrahedralize, check,
fracture, oracle, fuzz campaigns), which call it about every total/1000 items of each
stage and at its end, from the calling thread (fracture: or a worker, one at a time)
with the GIL held. Whatever it raises (KeyboardInterrupt included) stops the call and
propagates."""
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


def _resolve(progress: ProgressArg) -> Callable[[int, int, str], Any] | None | bool:
    """The callable, None (silent) or True (a bar or stderr lines)."""
    if progress is None or progress is False:
        return None
    if callable(progress):
        return progress
    if progress is True:
        return True
    raise ValueError(f"progress must be None, a bool or a callable, got {progress!r}")


class StageBar:
    """progress(done, total, stage) for a C++ loop: the user's callable, a tqdm bar
    reset at each stage, or (True without tqdm) a line on stderr as a stage starts and
    ends. `callback` is None when silent (the C++ loop then reports nothing)."""

    def __init__(self, progress: ProgressArg, label: str) -> None:
        self.label = label
        self._stage: str | None = None
        self._bar = None
        self._call: Callable[[int, int, str], Any] | None = None
        how = _resolve(progress)
        if callable(how):
            self._call = how
        elif how is True:
            try:
                from tqdm import tqdm
                self._bar = tqdm(total=0, desc=label, leave=False)
            except ImportError:
                self._call = self._line
        self.callback: Callable[[int, int, str], Any] | None = None if how is None else self

    def _line(self, done: int, total: int, stage: str) -> None:
        if stage != self._stage or done >= total:
            print(f"{self.label}: {stage} {done}/{total}", file=sys.stderr)
        self._stage = stage

    def __call__(self, done: int, total: int, stage: str) -> None:
        if self._bar is not None:
            if stage != self._stage:
                self._stage = stage
                self._bar.reset(total=total)
                self._bar.set_description(f"{self.label} {stage}")
            self._bar.update(done - self._bar.n)
        if self._call is not None:
            self._call(done, total, stage)

    def __enter__(self) -> StageBar:
        return self

    def __exit__(self, *exc: Any) -> None:
        if self._bar is not None:
            self._bar.close()
