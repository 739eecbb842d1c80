#!/usr/bin/python3
"""Checks scipy.spatial.Delaunay (Qhull) exactly with dtlab, next to dtlab's own result.

For each input (fuzz families and points sampled inside a mesh) it builds scipy's
Delaunay tetrahedralization and dtlab's, checks both with the exact checker and compares
them canonically. scipy's simplices go in as they come: their 3D orientations are mixed,
which dtlab.check's default orientation="any" accepts.

    PYTHONPATH=build/release/python /usr/bin/python3 python/examples/check_scipy.py
    ... check_scipy.py --points 5000 --families uniform,lattice,kettner_grid --mesh bunny.off

Exit status: 0 when dtlab's own result is valid on every input, 1 otherwise (scipy's
defects are what this measures, not an error).
"""
import argparse
import sys
import time

import numpy as np

import dtlab

try:
    from scipy.spatial import Delaunay
except ImportError:
    sys.exit("check_scipy.py needs scipy (Debian: apt-get install python3-scipy)")

DEFAULT_FAMILIES = "uniform,clustered,cospherical,lattice,duplicates,near_degenerate,kettner_grid"


def short(report: dtlab.CheckReport) -> str:
    if report.ok:
        return "valid"
    return ", ".join(f"{n} {k}" for k, n in report.counts.items() if n)


def run(name: str, points: np.ndarray) -> bool:
    t0 = time.perf_counter()
    ours = dtlab.tetrahedralize(points)
    t1 = time.perf_counter()
    our_check = dtlab.check(points, ours.tets, orientation="positive")
    try:
        t2 = time.perf_counter()
        qhull = Delaunay(points)
        t3 = time.perf_counter()
    except Exception as e:  # Qhull refuses some degenerate inputs (QhullError)
        print(f"{name:<18} {len(points):>6}  dtlab {len(ours.tets):>7} tets {t1 - t0:6.3f} s {short(our_check):<12}"
              f"  scipy: {type(e).__name__}")
        return our_check.ok
    simplices = qhull.simplices
    scipy_check = dtlab.check(points, simplices)
    verdict = dtlab.compare(points, simplices, ours.tets).verdict
    # Points Qhull left out of every simplex (exact or near repeats, "coplanar" to it).
    left_out = len(np.unique(qhull.coplanar[:, 0])) if len(qhull.coplanar) else 0
    print(f"{name:<18} {len(points):>6}  dtlab {len(ours.tets):>7} tets {t1 - t0:6.3f} s {short(our_check):<12}"
          f"  scipy {len(simplices):>7} tets {t3 - t2:6.3f} s {left_out:>5} left out  {short(scipy_check):<40}"
          f"  scipy vs dtlab: {verdict}")
    return our_check.ok


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=2000, help="points per input")
    ap.add_argument("--families", default=DEFAULT_FAMILIES, help="comma list of dtlab.fuzz families, or 'all'")
    ap.add_argument("--mesh", default="builtin", help="mesh to sample inside ('builtin': the bumpy torus)")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    families = list(dtlab.fuzz.families()) if a.families == "all" else [f for f in a.families.split(",") if f]
    print(f"scipy.spatial.Delaunay vs dtlab (adaptive + sos), every mesh checked exactly by dtlab.check")
    ok = True
    for family in families:
        ok &= run(family, dtlab.fuzz.generate(family, a.points, a.seed))
    for method in ("winding", "surface"):
        ok &= run(f"mesh:{method}", dtlab.sample(a.mesh, a.points, method=method, seed=a.seed))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
