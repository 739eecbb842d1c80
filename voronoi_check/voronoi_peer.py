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
#     tool's ridge neighbours and of its tets' neighbours (the tool's topology, the
#     adapter's vertices).
# Everything is in numpy arrays (ridges and regions as CSR rows, cells in blocks of
# 65536 sites written as they come): only cells that cross a wall and hull cells are
# clipped one by one (clip(), in Python). tests/adapter_identity.py holds the cells to
# those of the per-cell adapter before (tests/voronoi_peer_reference.py), byte for byte.
# Exit: 0 answered, 2 bad usage, 3 the tool refused (its message last on stderr), 4 not installed.
# The Python module imports the clipping part (scipy_topology, cells_from_ridges) as dtlab._voronoi_regions
# (dtlab.check_voronoi on a scipy.spatial.Voronoi): one adapter for both.
import itertools, struct, subprocess, sys, tempfile, time

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
            # clip's distances to a wall are +-x_a - c exactly (the other two products are
            # zeros, for finite vertices): a cell on the inner side of it is left as it is
            x = np.asarray(cell[0]).reshape(-1, 3)[:, a]
            if len(x) and np.isfinite(x).all() and ((x if side else -x) - c <= 0).all():
                continue
            cell = clip(cell[0], cell[1], cell[2], n, c, tag)
    return cell


class Rows:
    """Rows of integers in CSR form: row k is idx[off[k]:off[k + 1]] (int64 arrays)."""

    def __init__(self, off, idx):
        self.off, self.idx = np.asarray(off, dtype=np.int64), np.asarray(idx, dtype=np.int64)

    @staticmethod
    def of_lists(lists):
        lens = np.fromiter(map(len, lists), dtype=np.int64, count=len(lists))
        off = np.zeros(len(lists) + 1, dtype=np.int64)
        np.cumsum(lens, out=off[1:])
        return Rows(off, np.fromiter(itertools.chain.from_iterable(lists), dtype=np.int64, count=int(off[-1])))

    def __len__(self):
        return len(self.off) - 1

    def lens(self):
        return np.diff(self.off)

    def negatives(self):
        """Per row, how many of its entries are negative (-1: the vertex at infinity)."""
        c = np.zeros(len(self.idx) + 1, dtype=np.int64)
        np.cumsum(self.idx < 0, out=c[1:])
        return c[self.off[1:]] - c[self.off[:-1]]


def spans(starts, lens):
    """The concatenation of range(s, s + l) for the given starts and lengths."""
    total = int(lens.sum())
    first = np.zeros(len(lens), dtype=np.int64)
    np.cumsum(lens[:-1], out=first[1:])
    return np.repeat(starts - first, lens) + np.arange(total, dtype=np.int64)


class Ridges:
    """Qhull's ridges: sites p[r], q[r] and the polygon verts row r (-1 = infinity)."""

    def __init__(self, p, q, verts):
        self.p, self.q, self.verts = np.asarray(p, dtype=np.int64), np.asarray(q, dtype=np.int64), verts

    def __len__(self):
        return len(self.p)


def tet_neighbors(regions, wanted):
    """{site: sites} for the sites in `wanted` (a bool mask), from the Voronoi vertices
    that lie in exactly four regions: such a vertex is the centre of one Delaunay tet,
    and its six edges are Delaunay edges. A vertex in more regions (a merged, cospherical
    facet) tells nothing about its edges."""
    out = {}
    if not wanted.any() or len(regions.idx) == 0:
        return out
    flat_v = regions.idx
    flat_s = np.repeat(np.arange(len(regions), dtype=np.int64), regions.lens())
    finite = flat_v >= 0
    if not finite.any():
        return out
    count = np.bincount(flat_v[finite])
    # only the vertices of the wanted sites' regions can give them neighbours
    near = np.zeros(len(count), dtype=bool)
    near[flat_v[finite & wanted[flat_s]]] = True
    keep = finite.copy()
    keep[finite] = near[flat_v[finite]] & (count[flat_v[finite]] == 4)
    flat_v, flat_s = flat_v[keep], flat_s[keep]
    order = np.argsort(flat_v, kind="stable")
    for row in flat_s[order].reshape(-1, 4).tolist():  # the four sites of each such vertex
        for i in row:
            if wanted[i]:
                out.setdefault(i, set()).update(j for j in row if j != i)
    return out


def ridge_sides(pts, V, ridges, block=1 << 20):
    """Per ridge whose vertices are all finite: the sign of (fan normal of its polygon) .
    (q - p), the normal summed triangle by triangle from its first vertex in the polygon's
    order; 0 for ridges through infinity. The k-th fan triangles of a block of ridges in
    one numpy step, added in the same order as one ridge's."""
    m = len(ridges)
    side = np.zeros(m)
    lens, infinite = ridges.verts.lens(), ridges.verts.negatives()
    for b0 in range(0, m, block):
        b1 = min(m, b0 + block)
        rows = b0 + np.nonzero((lens[b0:b1] >= 3) & (infinite[b0:b1] == 0))[0]
        if len(rows) == 0:
            continue
        rows = rows[np.argsort(-lens[rows], kind="stable")]  # longest first: fan k is a prefix
        st, ln, idx = ridges.verts.off[rows], lens[rows], ridges.verts.idx
        o = V[idx[st]]
        nrm = np.zeros((len(rows), 3))
        for k in range(1, int(ln[0]) - 1):
            on = int(np.count_nonzero(ln > k + 1))
            a = V[idx[st[:on] + k]] - o[:on]
            b = V[idx[st[:on] + k + 1]] - o[:on]
            nrm[:on] += np.cross(a, b)
        d = pts[ridges.q[rows]] - pts[ridges.p[rows]]
        side[rows] = np.sign(nrm[:, 0] * d[:, 0] + nrm[:, 1] * d[:, 1] + nrm[:, 2] * d[:, 2])
    return side


class Cells:
    """Cells in CSR form, in any order of sites: cell c has nvert[c] vertices (rows of
    verts), nface[c] faces (their tags and corner counts fsize), then the corners (local
    vertex ids) of its faces."""

    def __init__(self, site, nvert, verts, nface, tags, fsize, corners):
        self.site, self.nvert, self.nface = site, nvert, nface
        self.verts, self.tags, self.fsize, self.corners = verts, tags, fsize, corners

    @staticmethod
    def of(cells):
        """From {site: (verts, faces, tags)} (the clipping's cells)."""
        items = sorted(cells.items())
        faces = [f for _, (_, fs, _) in items for f in fs]
        return Cells(np.array([i for i, _ in items], dtype=np.int64),
                     np.array([len(v) for _, (v, _, _) in items], dtype=np.int64),
                     np.asarray([x for _, (v, _, _) in items for x in v], dtype="<f8").reshape(-1, 3),
                     np.array([len(fs) for _, (_, fs, _) in items], dtype=np.int64),
                     np.asarray([t for _, (_, _, ts) in items for t in ts], dtype="<i4"),
                     np.array([len(f) for f in faces], dtype="<u4"),
                     np.asarray([v for f in faces for v in f], dtype="<u4"))

    def __len__(self):
        return len(self.site)

    def ncorner(self):
        return np.bincount(np.repeat(np.arange(len(self), dtype=np.int64), self.nface),
                           weights=self.fsize, minlength=len(self)).astype(np.int64)

    def pick(self, keep):
        """The cells where the bool mask keep is true."""
        def sub(counts):
            return spans((np.cumsum(counts) - counts)[keep], counts[keep])
        vi, fi, ci = sub(self.nvert), sub(self.nface), sub(self.ncorner())
        return Cells(self.site[keep], self.nvert[keep], self.verts[vi], self.nface[keep], self.tags[fi],
                     self.fsize[fi], self.corners[ci])

    def join(self, other):
        return Cells(*(np.concatenate([getattr(self, k), getattr(other, k)])
                       for k in ("site", "nvert", "verts", "nface", "tags", "fsize", "corners")))

    def as_dict(self):
        """{site: (verts (k, 3), faces as lists, tags as a list)}."""
        out, v0, f0, c0 = {}, 0, 0, 0
        for c in range(len(self)):
            nv, nf = int(self.nvert[c]), int(self.nface[c])
            sizes = self.fsize[f0:f0 + nf].tolist()
            faces = []
            flat = self.corners[c0:c0 + sum(sizes)].tolist()
            k = 0
            for s in sizes:
                faces.append(flat[k:k + s]); k += s
            out[int(self.site[c])] = (self.verts[v0:v0 + nv], faces, self.tags[f0:f0 + nf].tolist())
            v0, f0, c0 = v0 + nv, f0 + nf, c0 + k
        return out

    def words(self):
        """The cells as cell_exchange.hpp's records, in the order of their sites, as
        little-endian 32-bit words: per cell (i64 site, u32 vertex, face and corner
        counts), the vertices (3 f64 each), the faces' tags (i32), corner counts (u32) and
        corners (u32). Every field is a whole number of words."""
        k = len(self)
        nv, nf, nc = self.nvert, self.nface, self.ncorner()
        size = 5 + 6 * nv + 2 * nf + nc
        order = np.argsort(self.site, kind="stable")
        start = np.empty(k, dtype=np.int64)
        start[order] = np.cumsum(size[order]) - size[order]
        out = np.empty(int(size.sum()), dtype="<u4")
        head = np.empty(k, dtype=[("site", "<i8"), ("nv", "<u4"), ("nf", "<u4"), ("nc", "<u4")])
        head["site"], head["nv"], head["nf"], head["nc"] = self.site, nv, nf, nc
        out[start[:, None] + np.arange(5)] = head.view("<u4").reshape(k, 5)

        def rank(counts):  # per element: its cell, its place in the cell
            cell = np.repeat(np.arange(k, dtype=np.int64), counts)
            first = np.cumsum(counts) - counts
            return cell, np.arange(len(cell), dtype=np.int64) - first[cell]
        c, r = rank(nv)
        out[(start[c] + 5 + 6 * r)[:, None] + np.arange(6)] = \
            np.ascontiguousarray(self.verts, dtype="<f8").view("<u4").reshape(-1, 6)
        c, r = rank(nf)
        at = start[c] + 5 + 6 * nv[c] + r
        out[at] = self.tags.astype("<i4").view("<u4")
        out[at + nf[c]] = self.fsize
        c, r = rank(nc)
        out[start[c] + 5 + 6 * nv[c] + 2 * nf[c] + r] = self.corners
        return out


def bounded_cells(V, sites, e_start, e_count, e_ridge, e_nb, e_flip, ridges):
    """The cells of bounded regions from their ridges, all at once: cell c (site
    sites[c]) has the entries e_start[c] .. + e_count[c] (ridge, neighbour, whether the
    ridge's polygon is reversed to face the neighbour) as its faces, in that order; its
    vertices are the ridges' vertex ids sorted (-1, were there one, indexes V as
    numpy does), the corners their places in that list."""
    k = len(sites)
    e = spans(e_start, e_count)
    cell = np.repeat(np.arange(k, dtype=np.int64), e_count)
    r = e_ridge[e]
    fsize = ridges.verts.off[r + 1] - ridges.verts.off[r]
    pos = spans(np.zeros(len(e), dtype=np.int64), fsize)  # place in the face
    rep = np.repeat(np.arange(len(e), dtype=np.int64), fsize)
    back = np.repeat(e_flip[e], fsize)
    pos[back] = (fsize[rep] - 1 - pos)[back]
    gv = ridges.verts.idx[ridges.verts.off[r][rep] + pos]
    stride = len(V) + 1
    key = cell[rep] * stride + (gv + 1)
    uniq, local = np.unique(key, return_inverse=True)
    ucell = uniq // stride
    nvert = np.bincount(ucell, minlength=k).astype(np.int64)
    first = np.cumsum(nvert) - nvert
    local = local - first[cell[rep]]
    return Cells(np.asarray(sites, dtype=np.int64), nvert, V[uniq % stride - 1], e_count.astype(np.int64),
                 e_nb[e].astype("<i4"), fsize.astype("<u4"), local.astype("<u4"))


def clipped_cells(pts, V, ridges, regions, lo, hi, chunk=1 << 16):
    """The cells of the regions clipped to the box [lo, hi], as Cells blocks of at most
    `chunk` sites, in the order of their sites. ridges: Ridges; regions: Rows, per site
    its region's vertex ids (-1 = infinity; empty for a duplicate). A bounded region's
    cell: its ridge polygons as faces (turned to face the neighbour), clipped by the
    walls it crosses (walls(), per cell, only where a vertex lies outside the box). An
    unbounded region's cell (a hull site): the box cut by the bisectors of its ridge
    neighbours and of its tets' neighbours. Qhull lists a ridge only with three vertices
    or more, infinity counted once, so the face of a hull edge with one tet around it
    (one finite vertex and rays, a wedge of positive area) is in no ridge: an unbounded
    cell also takes the neighbours of its tets (tet_neighbors: the tool's own regions)."""
    n, m = len(regions), len(ridges)
    sides = ridge_sides(pts, V, ridges)
    # a face of p's cell faces q when its fan normal points to q's side; per site its
    # ridges in ridge order
    e_site = np.empty(2 * m, dtype=np.int64)
    e_site[0::2], e_site[1::2] = ridges.p, ridges.q
    order = np.argsort(e_site, kind="stable")
    e_site = e_site[order]
    e_ridge = order // 2
    e_nb = np.where(order % 2 == 0, ridges.q[e_ridge], ridges.p[e_ridge])
    e_flip = np.where(order % 2 == 0, sides[e_ridge] < 0, sides[e_ridge] > 0)
    del order
    bound = np.searchsorted(e_site, np.arange(n + 1, dtype=np.int64))
    e_count = np.diff(bound)
    reg_len, unbounded = regions.lens(), regions.negatives() > 0
    bounded = (reg_len > 0) & ~unbounded & (e_count > 0)
    unbounded &= reg_len > 0
    tets = tet_neighbors(regions, unbounded)
    lo_a, hi_a = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    for s0 in range(0, n, chunk):
        s1 = min(n, s0 + chunk)
        sites = s0 + np.nonzero(bounded[s0:s1])[0]
        block = bounded_cells(V, sites, bound[sites], e_count[sites], e_ridge, e_nb, e_flip, ridges)
        vin = ((block.verts >= lo_a) & (block.verts <= hi_a)).all(axis=1)
        inside = np.bincount(np.repeat(np.arange(len(sites)), block.nvert), weights=~vin,
                             minlength=len(sites)) == 0
        slow = {}
        if not inside.all():
            for i, (verts, faces, tags) in block.pick(~inside).as_dict().items():
                cell = walls((list(verts), faces, tags), lo, hi)
                if cell:
                    slow[i] = cell
            block = block.pick(inside)
        for i in (s0 + np.nonzero(unbounded[s0:s1])[0]).tolist():
            s, cell = pts[i], box_cell(lo, hi)
            for j in sorted(set(e_nb[bound[i]:bound[i + 1]].tolist()) | tets.get(i, set())):
                n_ = pts[j] - s
                cell = clip(cell[0], cell[1], cell[2], n_, float(np.dot(n_, (pts[j] + s) / 2)), j) if cell else None
            if cell:
                slow[i] = cell
        yield block.join(Cells.of(slow)) if slow else block


def cells_from_ridges(pts, V, ridges, regions, lo, hi):
    """{site: (verts, faces, tags)}: clipped_cells' cells as Python lists (faces and tags)."""
    out = {}
    for block in clipped_cells(pts, np.asarray(V, dtype=float), ridges, regions, lo, hi):
        out.update(block.as_dict())
    return out


def run_scipy(pts):
    from scipy.spatial import Voronoi
    t = time.perf_counter()
    vor = Voronoi(pts)
    sec = time.perf_counter() - t
    return sec, vor.vertices, *scipy_topology(vor)


def scipy_topology(vor):
    """(Ridges, regions per site as Rows) of a scipy.spatial.Voronoi, as clipped_cells
    takes them."""
    rp = np.asarray(vor.ridge_points, dtype=np.int64).reshape(-1, 2)
    ridges = Ridges(rp[:, 0], rp[:, 1], Rows.of_lists(vor.ridge_vertices))
    # scipy gives a copy of a site (a Qhull coplanar point) its original's region: the
    # first site of the region that is in a ridge keeps it (else its first site), the
    # other copies get none.
    pr = np.asarray(vor.point_region, dtype=np.int64)
    n = len(pr)
    in_ridges = np.zeros(n, dtype=bool)
    in_ridges[rp.ravel()] = True
    order = np.lexsort((np.arange(n), ~in_ridges, pr))
    lead = np.ones(n, dtype=bool)
    lead[1:] = pr[order][1:] != pr[order][:-1]
    owner = np.zeros(n, dtype=bool)
    owner[order[lead]] = True
    regs = Rows.of_lists(vor.regions)
    lens = np.where(owner, regs.lens()[pr], 0)
    off = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(lens, out=off[1:])
    return ridges, Rows(off, regs.idx[spans(regs.off[pr], lens)])


def line_tokens(buf, nl, a, b, dtype):
    """Lines a .. b-1 of buf (nl: the newlines' offsets) parsed as one stream of numbers."""
    lo = int(nl[a - 1]) + 1 if a > 0 else 0
    return np.fromstring(buf[lo:int(nl[b - 1]) + 1], dtype=dtype, sep=" ")


def count_rows(buf, nl, a, b, step=1 << 20):
    """Lines a .. b-1 of buf, each `k x1 .. xk` (Qhull's `o` regions and `Fv` ridges,
    single spaces), as Rows of their k numbers, the counts left out."""
    rows_off, rows_idx = [np.zeros(1, dtype=np.int64)], []
    at = 0
    arr = np.frombuffer(buf, dtype=np.uint8)
    for l0 in range(a, b, step):
        l1 = min(b, l0 + step)
        tok = line_tokens(buf, nl, l0, l1, np.int64)
        lo = int(nl[l0 - 1]) + 1
        spaces = np.flatnonzero(arr[lo:int(nl[l1 - 1]) + 1] == 32)
        ends = nl[l0:l1] - lo
        per_line = np.diff(np.searchsorted(spaces, ends), prepend=0) + 1
        first = np.cumsum(per_line) - per_line
        if int(per_line.sum()) == len(tok) and (tok[first] == per_line - 1).all():
            keep = np.ones(len(tok), dtype=bool)
            keep[first] = False
            rows_idx.append(tok[keep])
            rows_off.append(at + np.cumsum(per_line - 1))
        else:  # not single spaces: line by line, every number after the first
            lines = [[int(x) for x in line.split()[1:]] for line in buf[lo:int(nl[l1 - 1])].split(b"\n")]
            part = Rows.of_lists(lines)
            rows_idx.append(part.idx)
            rows_off.append(at + part.off[1:])
        at += len(rows_idx[-1])
    return Rows(np.concatenate(rows_off), np.concatenate(rows_idx) if rows_idx else np.zeros(0, np.int64))


def run_qvoronoi(pts):
    text = "3\n%d\n" % len(pts) + "".join("%r %r %r\n" % (float(p[0]), float(p[1]), float(p[2])) for p in pts)
    with tempfile.TemporaryFile() as out:
        t = time.perf_counter()
        r = subprocess.run(["qvoronoi", "o", "Fv"], input=text.encode(), stdout=out, stderr=subprocess.PIPE)
        sec = time.perf_counter() - t
        del text
        if r.returncode != 0:
            lines = [l for l in r.stderr.decode(errors="replace").splitlines() if l.strip()]
            qh = [l for l in lines if l.startswith("QH")]
            raise RuntimeError("qvoronoi: %s" % (qh or lines or ["exit %d" % r.returncode])[0])
        out.seek(0)
        buf = out.read()
    arr = np.frombuffer(buf, dtype=np.uint8)
    nl = np.concatenate([np.flatnonzero(arr[s:s + (1 << 26)] == 10) + s for s in range(0, len(buf), 1 << 26)]
                        or [np.zeros(0, np.int64)])
    nv, nr = map(int, line_tokens(buf, nl, 1, 2, np.int64)[:2])
    # `o`: the vertices (the first one stands for infinity), per site its region's
    # vertices (0 for infinity); `Fv`: per ridge its count, two sites and its vertices
    V = line_tokens(buf, nl, 3, 2 + nv, float)
    if len(V) != 3 * (nv - 1):
        raise RuntimeError("qvoronoi: unexpected output")
    V = V.reshape(-1, 3)
    regions = count_rows(buf, nl, 2 + nv, 2 + nv + nr)
    regions.idx -= 1
    at = 2 + nv + nr
    m = int(line_tokens(buf, nl, at, at + 1, np.int64)[0])
    f = count_rows(buf, nl, at + 1, at + 1 + m)
    del buf, arr, nl
    lens = f.lens() - 2
    p, q = f.idx[f.off[:-1]], f.idx[f.off[:-1] + 1]
    off = np.zeros(m + 1, dtype=np.int64)
    np.cumsum(lens, out=off[1:])
    idx = f.idx[spans(f.off[:-1] + 2, lens)] - 1
    return sec, V, Ridges(p, q, Rows(off, idx)), regions


def write(out, sec, blocks):
    """The cells file (cell_exchange.hpp): the blocks in the order of their sites."""
    with open(out, "wb") as f:
        f.write(b"DTLV"); f.write(struct.pack("<dQ", sec, 0))
        count = 0
        for block in blocks:
            if len(block):
                block.words().tofile(f)
                count += len(block)
        f.seek(4)
        f.write(struct.pack("<dQ", sec, count))


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
    write(sys.argv[3], sec, clipped_cells(pts, V, ridges, regions, b[:3], b[3:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
