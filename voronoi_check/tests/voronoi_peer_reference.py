# Frozen copy of voronoi_peer.py at main c6e3e29, before its array rewrite: the reference
# that tests/adapter_identity.py compares the adapter's cells files with. dtlab never runs it.
# The Python Voronoi peers of dtlab (voronoi_check/voronoi_peers.cpp runs this file):
#   voronoi_peer.py scipy|qvoronoi IN OUT XMIN YMIN ZMIN XMAX YMAX ZMAX
#   voronoi_peer.py --version scipy|qvoronoi
# IN: sites ("DTLP", u64 n, n x 3 f64); OUT: cells (voronoi_check/cell_exchange.hpp).
# scipy: scipy.spatial.Voronoi with its defaults; qvoronoi: Debian qhull-bin's
# `qvoronoi o Fv` with its defaults. Both give Voronoi vertices and ridges (a pair of
# sites and the polygon between them, with a vertex at infinity on unbounded ones);
# the adapter makes cells clipped to the box from them:
#   - a bounded cell: the tool's vertices, its ridge polygons as faces (turned to face
#     the neighbour), clipped by the box walls it crosses;
#   - an unbounded cell (a hull site): the box clipped by the bisectors of the
#     tool's ridge neighbours (the tool's topology, the adapter's vertices).
# Exit: 0 answered, 2 bad usage, 3 the tool refused (its message last on stderr), 4 not installed.
# The Python module imports the clipping part (cells_from_ridges) as dtlab._voronoi_regions
# (dtlab.check_voronoi on a scipy.spatial.Voronoi): one adapter for both.
import struct, subprocess, sys, time

try:
    import numpy as np
except Exception as e:
    print("not installed: %s" % e, file=sys.stderr); sys.exit(4)


def clip(verts, faces, tags, n, c, tag):
    """Keeps the part of a convex polytope with n.x <= c; None when nothing is left."""
    d = [float(np.dot(n, v) - c) for v in verts]
    if max(d) <= 0:
        return verts, faces, tags
    if min(d) >= 0:
        return None
    verts = list(verts)
    cut, out_f, out_t, on = {}, [], [], set()
    for f, t in zip(faces, tags):
        poly = []
        for k in range(len(f)):
            a, b = f[k], f[(k + 1) % len(f)]
            if d[a] <= 0:
                poly.append(a)
                if d[a] == 0:
                    on.add(a)
            if (d[a] < 0 < d[b]) or (d[b] < 0 < d[a]):
                key = (min(a, b), max(a, b))
                if key not in cut:
                    s = d[a] / (d[a] - d[b])
                    cut[key] = len(verts)
                    verts.append(verts[a] + s * (verts[b] - verts[a]))
                poly.append(cut[key])
                on.add(cut[key])
        if len(poly) >= 3:
            out_f.append(poly); out_t.append(t)
    cap = sorted(on)
    if len(cap) >= 3:
        o = sum(verts[i] for i in cap) / len(cap)
        u = verts[cap[0]] - o
        u = u / np.linalg.norm(u)
        w = np.cross(n / np.linalg.norm(n), u)
        cap.sort(key=lambda i: np.arctan2(np.dot(verts[i] - o, w), np.dot(verts[i] - o, u)))
        out_f.append(cap); out_t.append(tag)
    return compact(verts, out_f, out_t)


def compact(verts, faces, tags):
    used = sorted({v for f in faces for v in f})
    if len(faces) < 4:
        return None
    new = {v: k for k, v in enumerate(used)}
    return [verts[v] for v in used], [[new[v] for v in f] for f in faces], tags


def box_cell(lo, hi):
    v = [np.array([(hi if (k >> a) & 1 else lo)[a] for a in range(3)]) for k in range(8)]
    faces = [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1], [4, 5, 7, 6]]
    return v, faces, [-1, -2, -3, -4, -5, -6]


def walls(cell, lo, hi):
    for a in range(3):
        for side, tag in ((0, -1 - 2 * a), (1, -2 - 2 * a)):
            if cell is None:
                return None
            n = np.zeros(3); n[a] = 1.0 if side else -1.0
            c = hi[a] if side else -lo[a]
            cell = clip(cell[0], cell[1], cell[2], n, c, tag)
    return cell


def tet_neighbors(regions, wanted):
    """{site: sites} for the sites in `wanted`, from the Voronoi vertices that lie in
    exactly four regions: such a vertex is the centre of one Delaunay tet, and its six
    edges are Delaunay edges. A vertex in more regions (a merged, cospherical facet)
    tells nothing about its edges. In numpy: one pass over all region entries."""
    out = {}
    if not wanted:
        return out
    sizes = np.fromiter((len(r) for r in regions), dtype=np.int64, count=len(regions))
    flat_v = np.fromiter((v for r in regions for v in r), dtype=np.int64, count=int(sizes.sum()))
    flat_s = np.repeat(np.arange(len(regions), dtype=np.int64), sizes)
    finite = flat_v >= 0
    flat_v, flat_s = flat_v[finite], flat_s[finite]
    if flat_v.size == 0:
        return out
    four = np.bincount(flat_v)[flat_v] == 4
    flat_v, flat_s = flat_v[four], flat_s[four]
    order = np.argsort(flat_v, kind="stable")
    quads = flat_s[order].reshape(-1, 4)  # the four sites of each such vertex
    mask = np.zeros(len(regions), dtype=bool)
    mask[list(wanted)] = True
    for row in quads[mask[quads].any(axis=1)].tolist():
        for i in row:
            if mask[i]:
                out.setdefault(i, set()).update(j for j in row if j != i)
    return out


def ridge_sides(pts, V, ridges):
    """Per ridge (p, q, vs) whose vertices are all finite: the sign of (fan normal of the
    polygon vs) . (q - p), the normal summed triangle by triangle from vs[0] in the
    polygon's order; 0 for ridges through infinity. All ridges at once: the k-th fan
    triangles of every ridge in one numpy step, added in the same order as one ridge's."""
    m = len(ridges)
    side = np.zeros(m)
    lens = np.fromiter((len(vs) for _, _, vs in ridges), dtype=np.int64, count=m)
    if m == 0 or lens.max() < 3:
        return side
    width = int(lens.max())
    ids = np.full((m, width), -1, dtype=np.int64)
    for r, (_, _, vs) in enumerate(ridges):
        ids[r, :len(vs)] = vs
    finite = (ids >= 0) | (np.arange(width) >= lens[:, None])
    ok = finite.all(axis=1) & (lens >= 3)
    rows = np.nonzero(ok)[0]
    ids, lens = ids[rows], lens[rows]
    o = V[ids[:, 0]]
    nrm = np.zeros((len(rows), 3))
    for k in range(1, width - 1):
        on = k + 1 < lens
        if not on.any():
            break
        a = V[ids[on, k]] - o[on]
        b = V[ids[on, k + 1]] - o[on]
        nrm[on] += np.cross(a, b)
    pq = np.array([[p, q] for p, q, _ in ridges], dtype=np.int64)[rows]
    d = pts[pq[:, 1]] - pts[pq[:, 0]]
    side[rows] = np.sign(nrm[:, 0] * d[:, 0] + nrm[:, 1] * d[:, 1] + nrm[:, 2] * d[:, 2])
    return side


def cells_from_ridges(pts, V, ridges, regions, lo, hi):
    """ridges: (p, q, [vertex ids, -1 = infinity]); regions: per site its vertex ids
    (-1 = infinity; empty for a duplicate). Returns {site: (verts, faces, tags)}.
    Qhull lists a ridge only with three vertices or more, infinity counted once, so
    the face of a hull edge with one tet around it (one finite vertex and rays, a
    wedge of positive area) is in no ridge; an unbounded cell also takes the
    neighbours of its tets (tet_neighbors: the tool's own regions)."""
    sides = ridge_sides(pts, V, ridges)
    by_site = {}
    for r, (p, q, vs) in enumerate(ridges):
        # a face of p's cell faces q when its fan normal points to q's side
        by_site.setdefault(p, []).append((q, vs, sides[r] < 0))
        by_site.setdefault(q, []).append((p, vs, sides[r] > 0))
    lo_a, hi_a = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    tets = tet_neighbors(regions, {i for i, reg in enumerate(regions) if -1 in reg})
    cells = {}
    for i, reg in enumerate(regions):
        s, rs = pts[i], by_site.get(i, [])
        if not reg or (-1 not in reg and not rs):
            continue
        if -1 in reg:
            cell = box_cell(lo, hi)
            for j in sorted({j for j, _, _ in rs} | tets.get(i, set())):
                n = pts[j] - s
                cell = clip(cell[0], cell[1], cell[2], n, float(np.dot(n, (pts[j] + s) / 2)), j) if cell else None
        else:
            ids = sorted({v for _, vs, _ in rs for v in vs})
            local = {v: k for k, v in enumerate(ids)}
            verts = V[ids]
            faces, tags = [], []
            for j, vs, flip in rs:
                f = [local[v] for v in vs]
                if flip:
                    f.reverse()
                faces.append(f); tags.append(j)
            if ((verts >= lo_a) & (verts <= hi_a)).all():
                cell = (list(verts), faces, tags)  # inside the box: no wall cuts it
            else:
                cell = walls((list(verts), faces, tags), lo, hi)
        if cell:
            cells[i] = cell
    return cells


def run_scipy(pts):
    from scipy.spatial import Voronoi
    t = time.perf_counter()
    vor = Voronoi(pts)
    sec = time.perf_counter() - t
    return sec, vor.vertices, *scipy_topology(vor)


def scipy_topology(vor):
    """(ridges, regions per site) of a scipy.spatial.Voronoi, as cells_from_ridges takes them."""
    ridges = [(int(p), int(q), [int(v) for v in vs]) for (p, q), vs in zip(vor.ridge_points, vor.ridge_vertices)]
    # scipy gives a copy of a site (a Qhull coplanar point) its original's region: the
    # site in the ridges keeps it, the other copies get none.
    in_ridges = {int(i) for i in np.ravel(vor.ridge_points)}
    owner = {}
    for i, r in enumerate(vor.point_region):
        if r not in owner or (i in in_ridges and owner[r] not in in_ridges):
            owner[r] = i
    regions = [[int(v) for v in vor.regions[r]] if owner[r] == i else [] for i, r in enumerate(vor.point_region)]
    return ridges, regions


def run_qvoronoi(pts):
    text = "3\n%d\n" % len(pts) + "".join("%r %r %r\n" % (float(p[0]), float(p[1]), float(p[2])) for p in pts)
    t = time.perf_counter()
    r = subprocess.run(["qvoronoi", "o", "Fv"], input=text, capture_output=True, text=True)
    sec = time.perf_counter() - t
    if r.returncode != 0:
        lines = [l for l in r.stderr.splitlines() if l.strip()]
        qh = [l for l in lines if l.startswith("QH")]
        raise RuntimeError("qvoronoi: %s" % (qh or lines or ["exit %d" % r.returncode])[0])
    tok = r.stdout.split("\n")
    nv, nr = map(int, tok[1].split()[:2])
    V = np.array([[float(x) for x in tok[2 + k].split()] for k in range(1, nv)]).reshape(-1, 3)
    # `o`: per site its region's vertices, 0 for infinity
    regions = [[int(x) - 1 for x in tok[2 + nv + k].split()[1:]] for k in range(nr)]
    at = 2 + nv + nr
    ridges = []
    for line in tok[at + 1: at + 1 + int(tok[at])]:
        f = [int(x) for x in line.split()]
        ridges.append((f[1], f[2], [v - 1 for v in f[3:]]))
    return sec, V, ridges, regions


def write(out, sec, cells):
    with open(out, "wb") as f:
        f.write(b"DTLV"); f.write(struct.pack("<dQ", sec, len(cells)))
        for i in sorted(cells):
            verts, faces, tags = cells[i]
            corners = [v for fc in faces for v in fc]
            f.write(struct.pack("<qIII", i, len(verts), len(faces), len(corners)))
            f.write(np.asarray(verts, dtype="<f8").tobytes())
            f.write(np.asarray(tags, dtype="<i4").tobytes())
            f.write(np.asarray([len(fc) for fc in faces], dtype="<u4").tobytes())
            f.write(np.asarray(corners, dtype="<u4").tobytes())


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--version":
        if sys.argv[2] == "scipy":
            try:
                import scipy
            except Exception as e:
                print("not installed: %s" % e, file=sys.stderr); sys.exit(4)
            print("scipy %s (numpy %s)" % (scipy.__version__, np.__version__))
        else:
            try:
                r = subprocess.run(["qvoronoi", "-V"], capture_output=True, text=True)
            except OSError as e:
                print("not installed: %s" % e, file=sys.stderr); sys.exit(4)
            print("qvoronoi %s" % (r.stdout + r.stderr).strip().splitlines()[0])
        return 0
    if len(sys.argv) != 10 or sys.argv[1] not in ("scipy", "qvoronoi"):
        print("usage: voronoi_peer.py scipy|qvoronoi IN OUT XMIN YMIN ZMIN XMAX YMAX ZMAX", file=sys.stderr)
        return 2
    data = open(sys.argv[2], "rb").read()
    if data[:4] != b"DTLP":
        print("not a dtlab peer file", file=sys.stderr); return 2
    n = struct.unpack("<Q", data[4:12])[0]
    pts = np.frombuffer(data, dtype="<f8", count=3 * n, offset=12).reshape(n, 3)
    b = [float(x) for x in sys.argv[4:10]]
    try:
        if sys.argv[1] == "scipy":
            try:
                import scipy.spatial  # noqa: F401
            except Exception as e:
                print("not installed: %s" % e, file=sys.stderr); return 4
            sec, V, ridges, regions = run_scipy(pts)
        else:
            sec, V, ridges, regions = run_qvoronoi(pts)
    except FileNotFoundError as e:
        print("not installed: %s" % e, file=sys.stderr); return 4
    except Exception as e:
        lines = [l for l in str(e).splitlines() if l.strip()]
        qh = [l for l in lines if l.startswith("QH")]
        print("%s: %s" % (type(e).__name__, (qh or lines or ["?"])[0]), file=sys.stderr); return 3
    write(sys.argv[3], sec, cells_from_ridges(pts, V, ridges, regions, b[:3], b[3:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
