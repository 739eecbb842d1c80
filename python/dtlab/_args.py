"""The checks of the arguments of dtlab's functions: one implementation of each, shared
by dtlab, dtlab.fuzz and dtlab.spatial. A bad argument raises ValueError whose message
starts with the parameter's name and states the range the `dtlab` command states for
the same option; a bool, a string or a float where an integer is expected, and a string,
a bool, NaN or an infinity where a number is expected, are refused, never converted."""
from __future__ import annotations

import numbers
from collections.abc import Iterable
from typing import Any

import numpy as np


def _count(value: int, name: str, most: int = 2**63 - 1, least: int = 0) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not least <= int(value) <= most:
        top = "2^64-1" if most == 2**64 - 1 else str(most)
        raise ValueError(f"{name}: expected an integer in [{least}, {top}], got {value!r}")
    return int(value)


def _seed(seed: int, name: str = "seed") -> int:
    return _count(seed, name, 2**64 - 1)  # the CLI's --seed


def _threads(value: int) -> int:
    return _count(value, "threads", 1024)  # the CLI's bound of --threads


def _real(value: float, name: str, lo: float, hi: float, *, above: bool = False) -> float:
    """value as a float in [lo, hi] ((lo, hi] with above=True): a real number (a numpy
    scalar too), never a bool, a string, NaN or an infinity."""
    v = float("nan")
    if isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_)):
        try:
            v = float(value)
        except OverflowError:  # an int beyond the doubles
            pass
    if not (lo < v <= hi if above else lo <= v <= hi):
        raise ValueError(f"{name}: expected a number in {'(' if above else '['}{lo:g}, {hi:g}], got {value!r}")
    return v


def _items(values: Any, name: str, what: str = "a sequence") -> list[Any]:
    """list(values) for an argument that is a sequence: a scalar (or a string) is refused
    naming the parameter."""
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        raise ValueError(f"{name}: expected {what}, got {values!r}")
    return list(values)


def _reals(values: Any, name: str, count: int, lo: float, hi: float) -> tuple[float, ...]:
    """`count` numbers, each in [lo, hi] (the CLI's X,Y,Z options)."""
    what = f"{count} numbers in [{lo:g}, {hi:g}]"
    items = _items(values, name, what)
    if len(items) != count:
        raise ValueError(f"{name}: expected {what}, got {values!r}")
    return tuple(_real(v, name, lo, hi) for v in items)


def _peer_limits(timeout: float, memory_mb: float) -> tuple[float, float]:
    """The CLI's --timeout [0.001, 1e6] seconds and --memory [0, 1e9] MB of a peer's run."""
    return _real(timeout, "timeout", 1e-3, 1e6), _real(memory_mb, "memory_mb", 0, 1e9)
