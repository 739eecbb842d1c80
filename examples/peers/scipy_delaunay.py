#!/usr/bin/env python3
"""scipy.spatial.Delaunay as a dtlab peer: dtlab oracle pts.xyz --peer mine='python3 scipy_delaunay.py {in} {out}'"""
import sys
import numpy as np
from scipy.spatial import Delaunay

node, out = sys.argv[1], sys.argv[2]
pts = np.loadtxt(node, skiprows=1, usecols=(1, 2, 3), ndmin=2)  # TetGen .node, numbered from 0
tets = Delaunay(pts).simplices
with open(out + ".ele", "w") as f:
    f.write("%d 4 0\n" % len(tets))
    f.writelines("%d %d %d %d %d\n" % (i, *t) for i, t in enumerate(tets))
