"""What progress= costs tetrahedralize: None, a no-op callable and True (a tqdm bar, or
stderr lines without tqdm), alternated in one run (each round rotates the order, so a
change of load hits all three alike), on uniform points.

    PYTHONPATH=build/release/python /usr/bin/python3 python/benchmarks/progress_overhead.py --sizes 1e5,1e6 --rounds 5

Prints a markdown table: wall and CPU seconds of the call (min / median / max over the
rounds), the median's ratio to None's, the callbacks made, the CPU a callback adds, and
the load average before and after (under load, CPU time is the steadier measure). The bar's output goes to /dev/null (its formatting is measured, not a
terminal's drawing).
"""
from __future__ import annotations

import argparse
import contextlib
import os
import statistics
import sys
import time

import numpy as np

import dtlab

MODES = ("None", "no-op callable", "True")


def progress_arg(mode: str, counter: list[int]):
    if mode == "None":
        return None
    if mode == "True":
        return True

    def noop(done: int, total: int, stage: str) -> None:
        counter[0] += 1
    return noop


def timed(points: np.ndarray, mode: str) -> tuple[float, float, int]:
    """(wall s, CPU s, callbacks) of one build."""
    counter = [0]
    arg = progress_arg(mode, counter)
    with open(os.devnull, "w") as null, contextlib.redirect_stderr(null):
        w0, c0 = time.perf_counter(), time.process_time()
        dtlab.tetrahedralize(points, progress=arg)
        w1, c1 = time.perf_counter(), time.process_time()
    return w1 - w0, c1 - c0, counter[0]


def spread(xs: list[float]) -> str:
    return f"{min(xs):.4f} / {statistics.median(xs):.4f} / {max(xs):.4f}"


def measure(n: int, rounds: int, seed: int, notes: list[str]) -> list[str]:
    points = np.random.default_rng(seed).random((n, 3))
    timed(points, "None")  # warm-up: page faults of the first build
    wall: dict[str, list[float]] = {m: [] for m in MODES}
    cpu: dict[str, list[float]] = {m: [] for m in MODES}
    calls: dict[str, int] = {}
    for r in range(rounds):
        for m in MODES[r % 3:] + MODES[:r % 3]:
            w, c, k = timed(points, m)
            wall[m].append(w)
            cpu[m].append(c)
            calls[m] = k
    rows = []
    extra = (statistics.median(cpu["no-op callable"]) - statistics.median(cpu["None"])) / max(1, calls["no-op callable"])
    notes.append(f"n = {n}: a no-op callable adds {extra * 1e6:.2f} us of CPU per callback "
                 f"(difference of the CPU medians / callbacks)")
    for m in MODES:
        ratio_w = statistics.median(wall[m]) / statistics.median(wall["None"])
        ratio_c = statistics.median(cpu[m]) / statistics.median(cpu["None"])
        k = calls[m] if m == "no-op callable" else "-"
        rows.append(f"| {n} | {m} | {spread(wall[m])} | {ratio_w:.3f} | {spread(cpu[m])} | {ratio_c:.3f} | {k} |")
    return rows


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sizes", default="1e5,1e6", help="point counts, comma-separated")
    ap.add_argument("--rounds", type=int, default=5, help="runs of each mode per size")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args(argv)
    sizes = [int(float(s)) for s in a.sizes.split(",") if s]
    load0 = os.getloadavg()
    print(f"dtlab {dtlab.__version__}, {a.rounds} rounds, load average before {load0[0]:.2f} {load0[1]:.2f} {load0[2]:.2f}")
    print()
    print("| n | progress= | wall s (min / median / max) | median / None's | CPU s (min / median / max) "
          "| median / None's | callbacks |")
    print("| ---: | --- | --- | ---: | --- | ---: | ---: |")
    notes: list[str] = []
    for n in sizes:
        for row in measure(n, a.rounds, a.seed, notes):
            print(row, flush=True)
    load1 = os.getloadavg()
    print()
    for line in notes:
        print(line)
    print(f"load average after {load1[0]:.2f} {load1[1]:.2f} {load1[2]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
