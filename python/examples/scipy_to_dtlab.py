"""From "scipy gave me overlapping tets" to "dtlab gave the Delaunay tetrahedralization
and proved it", on an integer lattice (scipy#16094's case: a regular grid).

Run: PYTHONPATH=build/release/python python3 python/examples/scipy_to_dtlab.py [k]
"""
import sys

import numpy as np
import scipy.spatial

import dtlab
import dtlab.spatial

k = int(sys.argv[1]) if len(sys.argv) > 1 else 8
grid = np.stack(np.meshgrid(*[np.arange(k, dtype=float)] * 3, indexing="ij"), -1).reshape(-1, 3)
print(f"{len(grid)} points of a {k}x{k}x{k} integer grid")

# 1. scipy's answer, checked exactly (orientation "any": scipy's tets come in both orders).
qh = scipy.spatial.Delaunay(grid)
report = dtlab.check(grid, qh.simplices)
print(f"scipy.spatial.Delaunay: {qh.nsimplex} simplices -> {report.verdict}")
for d in report.defects[:3]:
    print(f"   e.g. {d.kind}: {d.detail}")

# 2. The same call on dtlab.spatial: same attributes, exact decisions.
tri = dtlab.spatial.Delaunay(grid)
print(f"dtlab.spatial.Delaunay: {tri.nsimplex} simplices -> {tri.check().verdict}")
print(f"   volume of the tets {np.abs(np.linalg.det(grid[tri.simplices][:, 1:] - grid[tri.simplices][:, :1])).sum() / 6:g}"
      f" = cube {(k - 1) ** 3}")

# 3. Points exactly on shared facets and edges: located, never -1 inside the hull.
on_edges = (grid[tri.simplices[:, 0]] + grid[tri.simplices[:, 1]]) / 2
print(f"find_simplex on {len(on_edges)} edge midpoints: {(tri.find_simplex(on_edges) < 0).sum()} outside (dtlab), "
      f"{(qh.find_simplex(on_edges) < 0).sum()} outside (scipy)")

# 4. Voronoi: one vertex per cube of cospherical points, merged by exact insphere tests.
vor = dtlab.spatial.Voronoi(grid)
print(f"dtlab.spatial.Voronoi: {len(vor.vertices)} vertices (cubes: {(k - 1) ** 3}), {len(vor.ridge_points)} ridges")
print(tri)
