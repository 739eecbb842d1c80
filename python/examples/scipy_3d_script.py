"""A typical scipy 3D script: linear interpolation on a Delaunay tetrahedralization,
the convex hull's volume and area, and Voronoi neighbours. Switching it to dtlab is
the import line only:

    from scipy.spatial import ConvexHull, Delaunay, Voronoi     # scipy
    from dtlab.spatial import ConvexHull, Delaunay, Voronoi     # dtlab

Run: python3 scipy_3d_script.py [uniform|lattice] [n]
(tests/test_example.py runs it both ways and compares the output.)
"""
import sys

import numpy as np
from scipy.spatial import ConvexHull, Delaunay, Voronoi

kind = sys.argv[1] if len(sys.argv) > 1 else "uniform"
n = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
rng = np.random.default_rng(0)
if kind == "lattice":
    k = round(n ** (1 / 3))
    points = np.stack(np.meshgrid(*[np.arange(k, dtype=float)] * 3, indexing="ij"), -1).reshape(-1, 3)
else:
    points = rng.random((n, 3))
values = points @ [1.0, 2.0, 3.0] + 4.0  # a linear field: interpolation must reproduce it

tri = Delaunay(points)
lo, hi = points.min(axis=0), points.max(axis=0)
queries = lo + rng.random((2000, 3)) * (hi - lo)
simplex = tri.find_simplex(queries)
inside = simplex >= 0
T = tri.transform[simplex[inside]]
b = np.einsum("ijk,ik->ij", T[:, :3], queries[inside] - T[:, 3])
weights = np.c_[b, 1 - b.sum(axis=1)]
interpolated = np.einsum("ij,ij->i", values[tri.simplices[simplex[inside]]], weights)
print(f"simplices: {tri.nsimplex}")
print(f"queries inside the hull: {inside.sum()} of {len(queries)}")
print(f"interpolation error: {np.abs(interpolated - queries[inside] @ [1.0, 2.0, 3.0] - 4.0).max():.1e}")
print(f"hull triangles: {len(tri.convex_hull)}")

hull = ConvexHull(points)
print(f"hull volume {hull.volume:.12g}, area {hull.area:.12g}, vertices {len(hull.vertices)}")

vor = Voronoi(points)
degree = np.bincount(vor.ridge_points.ravel(), minlength=len(points))
bounded = sum(1 for r in vor.regions if r and -1 not in r)
print(f"Voronoi vertices {len(vor.vertices)}, ridges {len(vor.ridge_points)}, bounded regions {bounded}, "
      f"mean neighbours {degree.mean():.4g}")
