#!/usr/bin/env python3
"""A deliberately wrong peer: scipy's Delaunay of the points rounded to float32, the
kind of bug a GPU port or a mesh file format introduces. Right on well-spread
points, wrong where points lie closer than float32 resolves."""
import sys
import numpy as np
from scipy.spatial import Delaunay

node, out = sys.argv[1], sys.argv[2]
pts = np.loadtxt(node, skiprows=1, usecols=(1, 2, 3), ndmin=2)
rounded = pts.astype(np.float32).astype(np.float64)
try:
    tets = Delaunay(rounded).simplices
except Exception as e:  # Qhull refuses flat input: say why, exit non-zero (verdict refused)
    sys.exit("qhull: %s" % str(e).splitlines()[0])
with open(out + ".ele", "w") as f:
    f.write("%d 4 0\n" % len(tets))
    f.writelines("%d %d %d %d %d\n" % (i, *t) for i, t in enumerate(tets))
