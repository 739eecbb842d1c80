"""dtlab's degeneracy point-set families, bit for bit those of `dtlab fuzz`.

    dtlab.fuzz.families()                       # {name: what it targets}
    dtlab.fuzz.generate("kettner_grid", 64, 7)  # (64, 3) float64
    dtlab.fuzz.case("near_degenerate", 3)       # case 3 of `dtlab fuzz --family near_degenerate`
    dtlab.fuzz.campaign(fn, cases=20)           # `dtlab fuzz --target` on your own Delaunay function
"""
from __future__ import annotations

import os
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Union

import numpy as np

from . import _core, _function_peer
from ._args import _count, _items, _peer_limits, _seed
from ._progress import ProgressArg, StageBar

_POINTS_MAX = 10**7  # the CLI's range of --points and --min-points: [1, 1e7]


def _points(value: int, name: str) -> int:
    return _count(value, name, _POINTS_MAX, 1)


def families() -> dict[str, str]:
    """Every family's name -> the degeneracy it targets, in `dtlab fuzz --list` order."""
    return dict(_core.fuzz_families())


def generate(family: str, n: int, seed: int) -> np.ndarray:
    """Exactly n points of `family` from `seed`, as an (n, 3) float64 array: the same
    bits on every IEEE-754 platform and the same as the CLI's for (family, n, seed)."""
    return _core.fuzz_generate(family, _points(n, "n"), _seed(seed))


def case_seed(seed: int, family: str, index: int) -> int:
    """The seed of case `index` of `family` in a campaign run with --seed `seed`."""
    return _core.fuzz_case_seed(_seed(seed), family, _seed(index, "index"))


def case_points(case_seed: int, min_points: int = 8, max_points: int = 64) -> int:
    """The number of points of a campaign case, drawn from its seed in [min_points, max_points]."""
    lo, hi = _points(min_points, "min_points"), _points(max_points, "max_points")
    if lo > hi:
        raise ValueError(f"min_points {lo} > max_points {hi}")
    return _core.fuzz_case_points(_seed(case_seed, "case_seed"), lo, hi)


def case(family: str, index: int, seed: int = 1, min_points: int = 8, max_points: int = 64) -> np.ndarray:
    """The points of case `index` of `family` in `dtlab fuzz --seed SEED --min-points MIN
    --points MAX` (the defaults are the CLI's)."""
    s = case_seed(seed, family, index)
    return generate(family, case_points(s, min_points, max_points), s)


@dataclass
class CaseResult:
    """One case of a peer campaign: the peer's verdict on case `index` of `family`
    (points: dtlab.fuzz.case(family, index, seed, min_points, max_points)) and, for a
    failure, the shrunk failing input (None when not shrunk: a hang, or shrink=False)."""
    family: str
    index: int
    case_seed: int
    n: int
    verdict: str
    message: str
    failed: bool
    lower_dimensional: bool
    seconds: float
    shrunk: np.ndarray | None = None
    shrunk_verdict: str | None = None  # the shrunk input run afresh
    minimal: bool = False              # 1-minimal: dropping any one point loses the failure
    shrink_stop: str = ""              # why not minimal ("runs": the budget, ...)
    shrink_runs: int = 0
    corpus_file: str = ""              # relative to `out` (only with out)


@dataclass
class FamilyResult:
    """Failures of one family with the 95% Wilson score interval of their rate."""
    cases: int
    failing: int
    rate: float
    low: float
    high: float
    verdicts: dict[str, int] = field(default_factory=dict)


@dataclass
class Campaign:
    peer: str
    families: dict[str, FamilyResult]
    cases: list[CaseResult]

    @property
    def failures(self) -> list[CaseResult]:
        return [c for c in self.cases if c.failed]


PeerTarget = Union[str, Callable[[np.ndarray], Any]]


def _peer_name(target: PeerTarget, name: str | None) -> str:
    if isinstance(target, str):
        return target
    if name is not None:
        return name
    guess = re.sub(r"[^A-Za-z0-9_.+-]", "", getattr(target, "__name__", ""))
    return guess if guess and guess not in ("lambda", "all", "none") else "python-peer"


def campaign(target: PeerTarget, families: Sequence[str] | str = "all", cases: int = 100, points: int = 64, seed: int = 1,
             out: str | os.PathLike[str] | None = None, *, min_points: int | None = None, shrink: bool = True,
             shrink_budget: int = 500, timeout: float = 600.0, memory_mb: float = 0.0,
             name: str | None = None, progress: ProgressArg = None) -> Campaign:
    """`dtlab fuzz --target PEER` from Python: case i of each family (the CLI's generators
    and case seeds, n drawn in [min_points, points]; min_points defaults to min(8, points)) goes to the peer, each run in its own
    process under `timeout` seconds and `memory_mb` MB (0: half the machine's) and judged
    by the exact checker; a failure (any verdict but delaunay; a refusal of a flat input
    is right) is shrunk by delta debugging to a 1-minimal input with the same verdict
    (within shrink_budget peer runs; hangs are not shrunk), as the CLI does.

    target: a peer name ("scipy", "qhull", "dtlab:naive", ...) or a callable
    (points (n, 3) float64) -> (m, 4) integer tets, run in a forked child as
    dtlab.oracle's peers are; `name` names it (default: its __name__; "python-peer" for a lambda). out: a folder
    for the corpus (<out>/corpus/*.node with a .json sidecar each, the CLI's files);
    None keeps the shrunk inputs in the result only. Returns a Campaign: per-family
    failure counts with Wilson intervals, and every case with its shrunk input. Cases
    run one at a time; Ctrl-C ends the running child and raises KeyboardInterrupt.

    progress: None, True (a tqdm bar) or a callable progress(done, total, family) after
    each case (and its shrink): the family's cases done, total = cases. What it raises
    (KeyboardInterrupt too) stops the campaign and propagates."""
    lo = min(8, _points(points, "points")) if min_points is None else _points(min_points, "min_points")  # the CLI's
    if out is not None and os.path.exists(out) and not os.path.isdir(out):
        raise ValueError(f"out: {os.fspath(out)!r} is not a directory")
    peer = _peer_name(target, name)
    functions = {} if isinstance(target, str) else _function_peer.runners({peer: target})
    if isinstance(families, str):
        families = [f for f in families.split(",") if f]
    families = _items(families, "families", "a family name or a sequence of them")
    names = [f for f in families if f != "all"]
    if len(names) < len(families):
        names = [n for n, _ in _core.fuzz_families()] + names
    names = list(dict.fromkeys(names))
    with StageBar(progress, "fuzz") as bar:
        # The CLI's ranges of --cases [1, 1e12], --shrink-budget [0, 1e9].
        raw = _core.fuzz_peer_campaign(peer, functions, names, _count(cases, "cases", 10**12, 1), lo,
                                       _points(points, "points"), _seed(seed), "" if out is None else os.fspath(out),
                                       bool(shrink), _count(shrink_budget, "shrink_budget", 10**9),
                                       *_peer_limits(timeout, memory_mb), bar.callback)
    results = [CaseResult(**c) for c in raw]
    per_family: dict[str, FamilyResult] = {}
    for f in names:
        mine = [c for c in results if c.family == f]
        failing = sum(c.failed for c in mine)
        rate, low, high = _core.wilson_interval(failing, len(mine))
        verdicts: dict[str, int] = {}
        for c in mine:
            verdicts[c.verdict] = verdicts.get(c.verdict, 0) + 1
        per_family[f] = FamilyResult(len(mine), failing, rate, low, high, verdicts)
    return Campaign(peer, per_family, results)
