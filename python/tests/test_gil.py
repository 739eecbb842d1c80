"""Long calls release the GIL: a Python thread keeps running while one is in C++."""
import threading
import time

import numpy as np

import dtlab


def max_gap_during(call):
    ticks, stop = [], threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.002)

    t = threading.Thread(target=ticker)
    t.start()
    time.sleep(0.05)
    start = time.perf_counter()
    call()
    end = time.perf_counter()
    stop.set()
    t.join()
    inside = [start] + [x for x in ticks if start <= x <= end] + [end]
    return max(b - a for a, b in zip(inside, inside[1:])), end - start


def test_tetrahedralize_and_check_release_the_gil():
    pts = np.random.default_rng(0).random((60_000, 3))
    built = []
    gap, total = max_gap_during(lambda: built.append(dtlab.tetrahedralize(pts)))
    assert total > 0.1, "the call is too short to tell"
    assert gap < total / 3, (gap, total)
    tets = built[0].tets
    gap, total = max_gap_during(lambda: dtlab.check(pts, tets))
    assert gap < max(total / 3, 0.05), (gap, total)
