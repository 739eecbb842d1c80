"""dtlab.spatial against scipy.spatial: equal on general-position input, valid (checked
exactly) on the lattice, cospherical and duplicate families where scipy's is not."""
import numpy as np
import pytest

import dtlab
from dtlab.spatial import ConvexHull, Delaunay, Voronoi

scipy_spatial = pytest.importorskip("scipy.spatial", reason="scipy (python3-scipy) is not installed")


def key(t):
    return tuple(sorted(int(v) for v in t))


@pytest.fixture(scope="module")
def general():
    return np.random.default_rng(11).random((2000, 3))


def test_delaunay_equals_scipy_on_general_position(general):
    ours, theirs = Delaunay(general), scipy_spatial.Delaunay(general)
    assert set(map(key, ours.simplices)) == set(map(key, theirs.simplices))
    assert ours.simplices.shape == theirs.simplices.shape and ours.simplices.dtype == np.int32
    v = general[ours.simplices]
    assert (np.linalg.det(v[:, 1:] - v[:, :1]) > 0).all()  # one handedness, right-handed
    assert set(map(key, ours.convex_hull)) == set(map(key, theirs.convex_hull))
    assert ours.check().ok


def test_find_simplex_equals_scipy_on_10k_queries(general):
    ours, theirs = Delaunay(general), scipy_spatial.Delaunay(general)
    q = np.random.default_rng(12).random((10_000, 3)) * 1.2 - 0.1
    a, b = ours.find_simplex(q), theirs.find_simplex(q)
    assert ((a < 0) == (b < 0)).all() and (a >= 0).sum() > 5000
    inside = a >= 0
    assert (np.sort(ours.simplices[a[inside]], 1) == np.sort(theirs.simplices[b[inside]], 1)).all()
    assert ours.find_simplex(q[:6].reshape(2, 3, 3)).shape == (2, 3)


def test_neighbors_are_consistent_and_scipys(general):
    ours, theirs = Delaunay(general), scipy_spatial.Delaunay(general)
    s, nb = ours.simplices, ours.neighbors
    for i in range(0, ours.nsimplex, 7):
        for j in range(4):
            n = nb[i, j]
            facet = set(s[i]) - {s[i, j]}
            if n < 0:
                assert tuple(sorted(facet)) in set(map(key, ours.convex_hull))
            else:
                assert facet <= set(s[n]) and i in nb[n] and s[i, j] not in s[n]
    # The same neighbour relation as scipy's, read through the common simplices.
    where = {key(t): i for i, t in enumerate(theirs.simplices)}
    for i in range(0, ours.nsimplex, 13):
        k = where[key(s[i])]
        mine = {key(s[n]) if n >= 0 else None for n in nb[i]}
        scipys = {key(theirs.simplices[n]) if n >= 0 else None for n in theirs.neighbors[k]}
        assert mine == scipys


def test_transform_and_equations(general):
    ours, theirs = Delaunay(general), scipy_spatial.Delaunay(general)
    where = {key(t): i for i, t in enumerate(theirs.simplices)}
    x = np.array([0.4, 0.5, 0.6])
    for i in range(0, ours.nsimplex, 97):
        k = where[key(ours.simplices[i])]
        def bary(tri, t):
            c = tri.transform[t, :3] @ (x - tri.transform[t, 3])
            return dict(zip(tri.simplices[t].tolist(), np.append(c, 1 - c.sum())))
        a, b = bary(ours, i), bary(theirs, k)
        assert max(abs(a[v] - b[v]) for v in a) < 1e-9
    # equations: the lifted hyperplane through each simplex, normal[3] < 0.
    z = ours.lift_points(general)[ours.simplices]
    eq = ours.equations
    assert np.abs(np.einsum("mkj,mj->mk", z, eq[:, :4]) + eq[:, 4:]).max() < 1e-9
    assert (eq[:, 3] < 0).all()
    # plane_distance > 0 for a simplex whose circumsphere holds x: the one holding x does.
    d = ours.plane_distance(x)
    assert d.shape == (ours.nsimplex,) and d[ours.find_simplex(x)] > 0
    assert ours.plane_distance(general[:5]).shape == (5, ours.nsimplex)


def test_vertex_attributes(general):
    ours = Delaunay(general)
    indptr, indices = ours.vertex_neighbor_vertices
    expected = [set() for _ in range(len(general))]
    for s in ours.simplices:
        for a in s:
            expected[a].update(set(s) - {a})
    assert [set(indices[indptr[k]:indptr[k + 1]].tolist()) for k in range(len(general))] == expected
    assert all(k in ours.simplices[ours.vertex_to_simplex[k]] for k in range(len(general)))
    assert ours.coplanar.shape == (0, 3)


@pytest.mark.parametrize("family", ["lattice", "cospherical", "duplicates", "kettner_grid", "near_degenerate"])
def test_degenerate_families_valid_where_scipy_is_not(family):
    pts = dtlab.fuzz.generate(family, 1000, seed=3)
    ours = Delaunay(pts)
    assert ours.check().ok
    assert dtlab.check(pts, ours.simplices, duplicates=ours.coplanar[:, 0]).ok
    hull = ours.convex_hull
    # find_simplex: no point of the hull's closure gets -1: the vertices, and for integer
    # points (where they are exact, not rounded off the hull) the tets' centroids and
    # the midpoints of hull edges.
    assert (ours.find_simplex(pts) >= 0).all()
    if (pts == np.round(pts)).all():
        cent = pts[ours.simplices].sum(axis=1) / 4
        assert (ours.find_simplex(cent) >= 0).all()
        assert (ours.find_simplex((pts[hull[:, 0]] + pts[hull[:, 1]]) / 2) >= 0).all()
    try:
        verdict = dtlab.check(pts, scipy_spatial.Delaunay(pts).simplices).verdict
    except Exception as e:  # Qhull refuses
        verdict = f"scipy raised {type(e).__name__}"
    print(f"{family}: dtlab valid, {ours.nsimplex} simplices; scipy: {verdict}")


def test_lattice_scipy_fails_our_check():
    pts = dtlab.fuzz.generate("lattice", 1000, seed=1)
    assert not dtlab.check(pts, scipy_spatial.Delaunay(pts).simplices).ok
    assert dtlab.check(pts, Delaunay(pts).simplices).ok


def test_duplicates_in_scipys_coplanar_layout():
    base = np.random.default_rng(3).random((50, 3))
    pts = np.concatenate([base, base[:10]])
    ours, theirs = Delaunay(pts), scipy_spatial.Delaunay(pts)
    assert sorted(ours.coplanar[:, 0]) == list(range(50, 60)) and len(theirs.coplanar) == 10
    assert (ours.coplanar[:, 2] == ours.coplanar[:, 0] - 50).all()
    assert all(c[2] in ours.simplices[c[1]] for c in ours.coplanar)
    assert (ours.vertex_to_simplex >= 0).all()
    assert (ours.find_simplex(pts) >= 0).all()


def test_query_on_a_facet_and_outside():
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
    ours = Delaunay(pts)
    assert ours.nsimplex == 2
    common = set(ours.simplices[0]) & set(ours.simplices[1])
    assert len(common) == 3
    on_facet = pts[sorted(common)].mean(axis=0)  # exactly representable: (1/3, 1/3, 1/3)
    assert ours.find_simplex(on_facet) in (0, 1)
    assert ours.find_simplex(pts).min() >= 0
    assert (ours.find_simplex([[2, 2, 2], [-1, 0, 0]]) == -1).all()


def test_convex_hull_equals_scipy(general):
    ours, theirs = ConvexHull(general), scipy_spatial.ConvexHull(general)
    assert set(map(key, ours.simplices)) == set(map(key, theirs.simplices))
    assert (ours.vertices == theirs.vertices).all()
    assert ours.volume == pytest.approx(theirs.volume, rel=1e-12)
    assert ours.area == pytest.approx(theirs.area, rel=1e-12)
    assert (general @ ours.equations[:, :3].T + ours.equations[:, 3]).max() < 1e-12
    nb = ours.neighbors
    for i in range(ours.nsimplex):
        for j in range(3):
            edge = set(ours.simplices[i]) - {ours.simplices[i, j]}
            assert edge <= set(ours.simplices[nb[i, j]]) and nb[i, j] != i


def test_convex_hull_of_a_lattice_merges_flat_faces():
    g = np.stack(np.meshgrid(*[np.arange(4.0)] * 3, indexing="ij"), -1).reshape(-1, 3)
    hull = ConvexHull(g)
    assert hull.volume == 27.0 and hull.area == 54.0
    assert int(hull.faces.max()) + 1 == 6  # six flat faces, proven coplanar exactly
    assert (hull.vertices == [0, 3, 12, 15, 48, 51, 60, 63]).all()  # the cube's corners
    assert (hull.vertices == scipy_spatial.ConvexHull(g).vertices).all()
    assert len(np.unique(hull.equations, axis=0)) == 6
    p = g[hull.simplices]
    normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert (np.einsum("ij,ij->i", normals, hull.equations[:, :3]) > 0).all()  # consistently outward


def test_voronoi_equals_scipy_on_general_position(general):
    ours, theirs = Voronoi(general), scipy_spatial.Voronoi(general)
    assert len(ours.vertices) == len(theirs.vertices)
    dist, match = scipy_spatial.cKDTree(theirs.vertices).query(ours.vertices)
    assert dist.max() < 1e-9 and len(set(match)) == len(match)
    m = {i: int(j) for i, j in enumerate(match)}
    m[-1] = -1
    mine = {key(p): key(m[v] for v in vs) for p, vs in zip(ours.ridge_points, ours.ridge_vertices)}
    scipys = {key(p): key(vs) for p, vs in zip(theirs.ridge_points, theirs.ridge_vertices)}
    assert mine == scipys
    for i in range(len(general)):
        assert key(m[v] for v in ours.regions[ours.point_region[i]]) == key(theirs.regions[theirs.point_region[i]])


def test_voronoi_ridges_are_cyclic(general):
    vor = Voronoi(general)
    for (p, q), vs in list(zip(vor.ridge_points, vor.ridge_vertices))[:500]:
        finite = [v for v in vs if v >= 0]
        if len(finite) < 3 or -1 in vs:
            continue
        x = vor.vertices[finite]
        n = general[q] - general[p]  # the ridge lies in the bisector: its polygon turns one way
        turns = [np.dot(np.cross(x[i] - x[0], x[i + 1] - x[0]), n) for i in range(1, len(x) - 1)]
        assert all(t > 0 for t in turns) or all(t < 0 for t in turns)


def test_voronoi_merges_cospherical_vertices_exactly():
    g = np.stack(np.meshgrid(*[np.arange(5.0)] * 3, indexing="ij"), -1).reshape(-1, 3)
    vor = Voronoi(g)
    assert len(vor.vertices) == 4 ** 3  # one per cube, not one per tet (6 or more per cube)
    assert len(np.unique(np.round(vor.vertices, 9), axis=0)) == 64
    # Face neighbours only, no diagonal ridges; as in Qhull, the 12 * 4 pairs along the
    # box's edges (one finite vertex and infinity) have none.
    assert len(vor.ridge_points) == 3 * 4 * 5 * 5 - 12 * 4 == len(scipy_spatial.Voronoi(g).ridge_points)
    interior = 2 * 25 + 2 * 5 + 2  # point (2, 2, 2): its cell is the cube around it, 8 vertices
    region = vor.regions[vor.point_region[interior]]
    assert len(region) == 8 and -1 not in region
    assert np.allclose(np.abs(vor.vertices[region] - g[interior]), 0.5)
    for r in vor.ridge_vertices:
        assert len(set(r)) == len(r)


def test_incremental_and_options_accepted(general):
    a = Delaunay(general[:100], incremental=True, qhull_options="Qbb Qc Qz")
    a.add_points(general[100:500])
    b = Delaunay(general[:500])
    assert set(map(key, a.simplices)) == set(map(key, b.simplices))
    a.close()
    with pytest.raises(RuntimeError):
        a.add_points(general[500:510])
    with pytest.raises(ValueError):
        Delaunay(general[:, :2])
    with pytest.raises(ValueError):
        Delaunay(np.ma.masked_all((5, 3)))
    with pytest.raises(ValueError):
        Voronoi(general, furthest_site=True)


def test_repr_and_progress(general):
    calls = []
    tri = Delaunay(general, progress=lambda done, total, stage: calls.append((done, total, stage)))
    assert [c[0] for c in calls] == [1, 2, 3] and calls[-1][1] == 3
    r = repr(tri)
    assert "2000 points" in r and f"{tri.nsimplex} simplices" in r and "s;" in r
    assert "<code>" in tri._repr_html_()
