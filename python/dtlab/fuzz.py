"""dtlab's degeneracy point-set families, bit for bit those of `dtlab fuzz`.

    dtlab.fuzz.families()                       # {name: what it targets}
    dtlab.fuzz.generate("kettner_grid", 64, 7)  # (64, 3) float64
    dtlab.fuzz.case("near_degenerate", 3)       # case 3 of `dtlab fuzz --family near_degenerate`
"""
from __future__ import annotations

import numpy as np

from . import _core


def _uint(value: int, name: str, bits: int = 64) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= int(value) < 2**bits:
        raise ValueError(f"{name}: expected an integer in [0, 2^{bits}), got {value!r}")
    return int(value)


def families() -> dict[str, str]:
    """Every family's name -> the degeneracy it targets, in `dtlab fuzz --list` order."""
    return dict(_core.fuzz_families())


def generate(family: str, n: int, seed: int) -> np.ndarray:
    """Exactly n points of `family` from `seed`, as an (n, 3) float64 array: the same
    bits on every IEEE-754 platform and the same as the CLI's for (family, n, seed)."""
    return _core.fuzz_generate(family, _uint(n, "n"), _uint(seed, "seed"))


def case_seed(seed: int, family: str, index: int) -> int:
    """The seed of case `index` of `family` in a campaign run with --seed `seed`."""
    return _core.fuzz_case_seed(_uint(seed, "seed"), family, _uint(index, "index"))


def case_points(case_seed: int, min_points: int = 8, max_points: int = 64) -> int:
    """The number of points of a campaign case, drawn from its seed in [min_points, max_points]."""
    lo, hi = _uint(min_points, "min_points"), _uint(max_points, "max_points")
    if lo > hi:
        raise ValueError(f"min_points {lo} > max_points {hi}")
    return _core.fuzz_case_points(_uint(case_seed, "case_seed"), lo, hi)


def case(family: str, index: int, seed: int = 1, min_points: int = 8, max_points: int = 64) -> np.ndarray:
    """The points of case `index` of `family` in `dtlab fuzz --seed SEED --min-points MIN
    --points MAX` (the defaults are the CLI's)."""
    s = case_seed(seed, family, index)
    return generate(family, case_points(s, min_points, max_points), s)
