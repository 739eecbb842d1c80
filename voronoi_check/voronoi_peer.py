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


def cells_from_ridges(pts, V, ridges, lo, hi):
    """ridges: (p, q, [vertex ids, -1 = infinity]). Returns {site: (verts, faces, tags)}."""
    by_site = {}
    for p, q, vs in ridges:
        by_site.setdefault(p, []).append((q, vs))
        by_site.setdefault(q, []).append((p, vs))
    cells = {}
    for i, rs in by_site.items():
        s = pts[i]
        if any(-1 in vs for _, vs in rs):
            cell = box_cell(lo, hi)
            for j, _ in rs:
                n = pts[j] - s
                cell = clip(cell[0], cell[1], cell[2], n, float(np.dot(n, (pts[j] + s) / 2)), j) if cell else None
        else:
            ids = sorted({v for _, vs in rs for v in vs})
            local = {v: k for k, v in enumerate(ids)}
            verts = [V[v] for v in ids]
            faces, tags = [], []
            for j, vs in rs:
                f = [local[v] for v in vs]
                nrm = np.zeros(3)
                for k in range(1, len(f) - 1):
                    nrm += np.cross(verts[f[k]] - verts[f[0]], verts[f[k + 1]] - verts[f[0]])
                if np.dot(nrm, pts[j] - s) < 0:
                    f.reverse()
                faces.append(f); tags.append(j)
            cell = walls((verts, faces, tags), lo, hi)
        if cell:
            cells[i] = cell
    return cells


def run_scipy(pts):
    from scipy.spatial import Voronoi
    t = time.perf_counter()
    vor = Voronoi(pts)
    sec = time.perf_counter() - t
    ridges = [(int(p), int(q), [int(v) for v in vs]) for (p, q), vs in zip(vor.ridge_points, vor.ridge_vertices)]
    return sec, vor.vertices, ridges


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
    at = 2 + nv + nr
    ridges = []
    for line in tok[at + 1: at + 1 + int(tok[at])]:
        f = [int(x) for x in line.split()]
        ridges.append((f[1], f[2], [v - 1 for v in f[3:]]))
    return sec, V, ridges


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
            sec, V, ridges = run_scipy(pts)
        else:
            sec, V, ridges = run_qvoronoi(pts)
    except FileNotFoundError as e:
        print("not installed: %s" % e, file=sys.stderr); return 4
    except Exception as e:
        lines = [l for l in str(e).splitlines() if l.strip()]
        qh = [l for l in lines if l.startswith("QH")]
        print("%s: %s" % (type(e).__name__, (qh or lines or ["?"])[0]), file=sys.stderr); return 3
    write(sys.argv[3], sec, cells_from_ridges(pts, V, ridges, b[:3], b[3:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
