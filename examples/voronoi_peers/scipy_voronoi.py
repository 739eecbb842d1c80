# A Voronoi peer given by a command: scipy.spatial.Voronoi, its cells clipped to the
# box and written as dtlab's JSON cells file (README: "Judge your own code").
#   dtlab voronoi pts.xyz --against mine \
#     --voronoi-peer 'mine=/usr/bin/python3 examples/voronoi_peers/scipy_voronoi.py {in} {box} {out}'
# {in}: the sites as a TetGen .node (0-based); {box}: xmin ymin zmin xmax ymax zmax;
# writes {out}.json. The clipping is the built-in scipy-voronoi adapter's
# (voronoi_check/voronoi_peer.py, imported), so this peer and the built-in one differ
# only in how the cells travel. --flip-faces reverses every other face (dtlab turns each
# face outward itself: faces may come in any orientation).
import json, os, sys, time

import numpy as np
from scipy.spatial import Voronoi

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "voronoi_check"))
from voronoi_peer import cells_from_ridges, scipy_topology  # noqa: E402

args = [a for a in sys.argv[1:] if a != "--flip-faces"]
node, box, out = args[0], [float(x) for x in args[1:7]], args[7]
rows = [l.split("#")[0].split() for l in open(node)]
rows = [r for r in rows if r]
pts = np.array([[float(x) for x in r[1:4]] for r in rows[1:1 + int(rows[0][0])]]).reshape(-1, 3)
t = time.perf_counter()
vor = Voronoi(pts)
seconds = time.perf_counter() - t
ridges, regions = scipy_topology(vor)
cells = []
for site, (verts, faces, neighbors) in sorted(cells_from_ridges(pts, vor.vertices, ridges, regions, box[:3], box[3:]).items()):
    if "--flip-faces" in sys.argv:
        faces = [f[::-1] if k % 2 else f for k, f in enumerate(faces)]
    cells.append({"site": site, "vertices": [[float(c) for c in v] for v in verts],
                  "faces": [[int(i) for i in f] for f in faces], "neighbors": [int(j) for j in neighbors]})
with open(out + ".json", "w") as f:
    json.dump({"cells": cells, "seconds": seconds}, f)
