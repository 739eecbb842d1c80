"""dtlab.check_voronoi: dtlab's and scipy's cells judged by the exact Voronoi checker."""
import numpy as np
import pytest

import dtlab


def test_our_cells_and_scipys_are_exact_on_random_points():
    pts = np.random.default_rng(1).random((200, 3))
    r = dtlab.check_voronoi(pts, dtlab.voronoi(pts))
    assert r["verdict"] == "exact-topology" and r["cells"] == 200
    scipy_spatial = pytest.importorskip("scipy.spatial")
    r = dtlab.check_voronoi(pts, scipy_spatial.Voronoi(pts), box=(-0.1, -0.1, -0.1, 1.1, 1.1, 1.1))
    assert r["verdict"] == "exact-topology", r["counts"]


def test_a_dropped_cell_is_wrong_topology():
    pts = np.random.default_rng(2).random((50, 3))
    vd = dtlab.voronoi(pts)
    cells = [(c.site, c.vertices, c.faces, c.face_neighbors) for c in vd.cells[1:]]
    r = dtlab.check_voronoi(pts, cells, box=vd.box)
    assert r["verdict"] == "wrong-topology"
    assert r["counts"]["missing-cell"] == 1


def test_coplanar_points_are_refused():
    with pytest.raises(ValueError):
        dtlab.check_voronoi(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.0]]), [], box=(-1, -1, -1, 2, 2, 2))


def test_scipy_cells_of_hull_edges_with_one_tet():
    # Qhull lists a ridge only with 3 vertices (infinity once): on one tet scipy has no
    # ridge at all, and the adapter takes the 6 neighbours from the regions
    # (voronoi_check/corpus/scipy-voronoi-uniform-n25-1.node).
    scipy_spatial = pytest.importorskip("scipy.spatial")
    pts = np.array([[0.9577314449920443, 0.6327793038290165, 0.15208938114568094],
                    [0.3349229014298386, 0.735562357242233, 0.6843961158156141],
                    [0.5570683787113921, 0.30868276277966955, 0.6176198020723661],
                    [0.811109233013189, 0.034099984568699226, 0.4751613964455029]])
    vor = scipy_spatial.Voronoi(pts)
    assert len(vor.ridge_points) == 0
    r = dtlab.check_voronoi(pts, vor)
    assert r["verdict"] == "exact-topology", r["counts"]
    assert r["cells"] == 4 and r["voronoi_edges"] == 12


def test_ulp_floor_judges_far_translate():
    # Sites at ~2^30..2^40 a few ulps apart: one ulp is up to a quarter of the box, below
    # which the relative tolerances lie; dtlab.voronoi answers these cells since the floor.
    pts = dtlab.fuzz.generate("far_translate", 48, 3)
    vd = dtlab.voronoi(pts)
    r = dtlab.check_voronoi(pts, vd)
    assert r["verdict"] == "exact-topology", r["counts"]
    assert r["tolerances"]["vertex"]["rule"] == "ulps" and r["tolerances"]["volume"]["rule"] == "ulps"
    assert r["max_vertex_ulps"] <= 4
    relative = dtlab.check_voronoi(pts, vd, ulps=0)
    assert relative["verdict"] == "volume-mismatch" and relative["counts"]["vertex-off"] > 0
    with pytest.raises(ValueError):
        dtlab.check_voronoi(pts, vd, ulps=-1)


def test_cells_with_non_integer_ids_are_refused_not_truncated():
    # A face index 1.7 was cast to 1 by np.asarray(..., uint32): cells with shifted
    # float indices judged exact-topology (docs/probe3.md, "Not probed").
    pts = np.random.default_rng(4).random((30, 3))
    vd = dtlab.voronoi(pts)
    cells = [(c.site, c.vertices, [list(f) for f in c.faces], c.face_neighbors) for c in vd.cells]
    assert dtlab.check_voronoi(pts, cells, box=vd.box)["verdict"] == "exact-topology"
    site, verts, faces, nbrs = cells[0]
    for bad, message in [
        ((site, verts, [[x + 0.7 for x in f] for f in faces], nbrs), "face 0: expected integer ids"),
        ((site, verts, [[True, False, True]] + faces[1:], nbrs), "face 0: expected integer ids"),
        ((site, verts, [[-1, 0, 1]] + faces[1:], nbrs), "face 0 corner -1 is out of range"),
        ((site, verts, [[0, 1, len(verts)]] + faces[1:], nbrs), "out of range"),
        ((0.5, verts, faces, nbrs), "site: expected an integer id"),
        ((site, verts, faces, np.asarray(nbrs, dtype=np.float64)), "neighbours: expected integer ids"),
        ((site, verts, faces, [-7] * len(nbrs)), r"neighbours: -7 is out of range \[-6, 2147483647\]"),
    ]:
        with pytest.raises(ValueError, match=message):
            dtlab.check_voronoi(pts, [bad] + cells[1:], box=vd.box)


def test_a_scipy_voronoi_of_other_points_is_refused():
    scipy_spatial = pytest.importorskip("scipy.spatial")
    pts = np.random.default_rng(5).random((30, 3))
    with pytest.raises(ValueError, match="other points"):
        dtlab.check_voronoi(pts, scipy_spatial.Voronoi(pts[::-1].copy()))
    with pytest.raises(ValueError, match="other points"):
        dtlab.check_voronoi(pts[:29], scipy_spatial.Voronoi(pts))


def test_thread_counts_are_bounded_as_in_the_cli():
    pts = np.random.default_rng(6).random((30, 3))
    for threads in (1025, 10**6, 2**70, -1, 1.5, True):
        with pytest.raises(ValueError, match="threads"):
            dtlab.voronoi(pts, threads=threads)
        with pytest.raises(ValueError, match="threads"):
            dtlab.tetrahedralize(pts, threads=threads)
    assert len(dtlab.voronoi(pts, threads=1024).cells) == 30


def _without_seconds(report):
    return {k: v for k, v in report.items() if not k.startswith("seconds")}


def test_threads_give_the_same_report():
    pts = np.random.default_rng(4).random((3000, 3))
    vd = dtlab.voronoi(pts)
    # A damaged copy too, so that the defects and witnesses are compared as well.
    cells = [(c.site, c.vertices, c.faces, c.face_neighbors) for i, c in enumerate(vd.cells) if i % 97 != 3]
    for tool in (vd, cells):
        one = dtlab.check_voronoi(pts, tool, box=vd.box, threads=1)
        for threads in (2, 3, 0):
            assert _without_seconds(dtlab.check_voronoi(pts, tool, box=vd.box, threads=threads)) == _without_seconds(one)
    assert one["verdict"] == "wrong-topology" and one["counts"]["missing-cell"] == 31
    with pytest.raises(ValueError, match="^threads: "):
        dtlab.check_voronoi(pts, vd, threads=-1)


def _damaged(pts, vd, replace):
    """vd's cells as (site, vertices, faces, neighbours) lists with cell 0's parts replaced."""
    cells = [(c.site, c.vertices, [list(f) for f in c.faces], c.face_neighbors) for c in vd.cells]
    cells[0] = replace(*cells[0])
    return cells


def test_ids_are_range_checked_before_the_narrowing_cast():
    # A corner k + 2^32 was cast to uint32 before the range check and read as k: the
    # cell was judged exact-topology; site 2^64-1 was reported as -1, 2^63 as -2^63,
    # a neighbour 2^64 as a float64 (probe 6, finds 4 and 6).
    pts = np.random.default_rng(7).random((30, 3))
    vd = dtlab.voronoi(pts)
    nv = len(vd.cells[0].vertices)
    k = int(vd.cells[0].faces[2][0])
    wrapped = k + 2**32
    for face in ([wrapped] + [int(x) for x in vd.cells[0].faces[2][1:]],
                 np.array([wrapped, *vd.cells[0].faces[2][1:]], dtype=np.int64),
                 np.array([wrapped, *vd.cells[0].faces[2][1:]], dtype=np.uint64)):
        cells = _damaged(pts, vd, lambda s, v, f, n: (s, v, f[:2] + [face] + f[3:], n))
        with pytest.raises(ValueError, match=rf"^cells\[0\]: face 2 corner {wrapped} is out of range "
                                             rf"\(the cell has {nv} vertices\)$"):
            dtlab.check_voronoi(pts, cells, box=vd.box)
    nbrs = list(vd.cells[0].face_neighbors)

    def site(x):
        return lambda s, v, f, n: (x, v, f, n)

    def neighbours(x):
        return lambda s, v, f, n: (s, v, f, x)

    for replace, message in [
        (site(np.uint64(2**64 - 1)),
         r"^cells\[0\]: site: 18446744073709551615 is out of range \[0, 9223372036854775807\]$"),
        (site(2**63), r"^cells\[0\]: site: 9223372036854775808 is out of range"),
        (site(np.int64(-1)), r"^cells\[0\]: site: -1 is out of range"),
        (site(True), r"^cells\[0\]: site: expected an integer id, got True$"),
        (neighbours([2**64] + nbrs[1:]),
         r"^cells\[0\]: neighbours: 18446744073709551616 is out of range \[-6, 2147483647\]$"),
        (neighbours(np.array([2**64 - 1] + nbrs[1:], dtype=np.uint64)),
         r"^cells\[0\]: neighbours: 18446744073709551615 is out of range"),
        (neighbours(np.array([2**31] + nbrs[1:], dtype=np.int64)),
         r"^cells\[0\]: neighbours: 2147483648 is out of range"),
        (neighbours([-2**40] + nbrs[1:]), r"^cells\[0\]: neighbours: -1099511627776 is out of range"),
        # numpy reads [True, 1, 2] as int64: a bool among the ids is refused by name.
        (neighbours([True] + [int(x) for x in nbrs[1:]]), r"^cells\[0\]: neighbours: expected integer ids, got True$"),
        (neighbours(nbrs[1:]),
         rf"^cells\[0\]: cell of site 0: {len(nbrs) - 1} face neighbours for {len(nbrs)} faces \(one per face\)$"),
        (neighbours(np.asarray(nbrs).reshape(1, -1)), r"^cells\[0\]: neighbours: expected a 1-d"),
        (lambda s, v, f, n: (s, v, [[0, 1]] + f[1:], n),
         r"^cells\[0\]: cell of site 0: face 0 has 2 corners \(a face needs at least 3\)$"),
        (lambda s, v, f, n: (s, v, [[True] + f[0][1:]] + f[1:], n),
         r"^cells\[0\]: face 0: expected integer ids, got True$"),
    ]:
        with pytest.raises(ValueError, match=message):
            dtlab.check_voronoi(pts, _damaged(pts, vd, replace), box=vd.box)
    # In range, every integer type is taken as it is.
    cells = _damaged(pts, vd, lambda s, v, f, n: (np.uint64(s), v, [np.asarray(x, np.uint64) for x in f],
                                                  np.asarray(n, np.int16)))
    assert dtlab.check_voronoi(pts, cells, box=vd.box)["verdict"] == "exact-topology"


def test_add_cells_refusals_name_the_cell_by_its_index():
    # ToolCells::add_cell's messages name only the site; the binding names cells[k]
    # (the Python side no longer repeats these two checks).
    pts = np.random.default_rng(9).random((30, 3))
    vd = dtlab.voronoi(pts)
    k = 5
    base = [(c.site, c.vertices, [list(f) for f in c.faces], list(c.face_neighbors)) for c in vd.cells]
    s, v, f, n = base[k]
    for cell, message in [
        ((s, v, f[:3] + [f[3][:2]] + f[4:], n),
         rf"^cells\[{k}\]: cell of site {s}: face 3 has 2 corners \(a face needs at least 3\)$"),
        ((s, v, f, n + [n[0]]),
         rf"^cells\[{k}\]: cell of site {s}: {len(n) + 1} face neighbours for {len(f)} faces \(one per face\)$"),
        ((s, v, [], n[:1]), rf"^cells\[{k}\]: cell of site {s}: 1 face neighbours for 0 faces \(one per face\)$"),
    ]:
        cells = base[:k] + [cell] + base[k + 1:]
        with pytest.raises(ValueError, match=message):
            dtlab.check_voronoi(pts, cells, box=vd.box)
    # The undamaged list is judged exact.
    assert dtlab.check_voronoi(pts, base, box=vd.box)["verdict"] == "exact-topology"


def test_cell_vertices_must_be_k_by_3():
    # reshape(-1, 3) read a (3, k) transpose or a flat (3k,) array as other points
    # (probe 6, find 5).
    pts = np.random.default_rng(8).random((30, 3))
    vd = dtlab.voronoi(pts)
    v = np.asarray(vd.cells[0].vertices)
    k = len(v)
    for bad, message in [
        (v.T, rf"^cells\[0\]: vertices must be \(k, 3\), got \(3, {k}\)$"),
        (v.T.tolist(), rf"^cells\[0\]: vertices must be \(k, 3\), got \(3, {k}\)$"),
        (v.reshape(-1), rf"^cells\[0\]: vertices must be \(k, 3\), got \({3 * k},\)$"),
        (v.reshape(-1).tolist(), rf"^cells\[0\]: vertices must be \(k, 3\), got \({3 * k},\)$"),
        (v[:, :2], rf"^cells\[0\]: vertices must be \(k, 3\), got \({k}, 2\)$"),
        (v[None], rf"^cells\[0\]: vertices must be \(k, 3\), got \(1, {k}, 3\)$"),
        ([list(v[0][:2])] + v[1:].tolist(), r"^cells\[0\]: vertices must be \(k, 3\), got rows of 2, 3 coordinates$"),
        (v > 0.5, r"^cells\[0\]: vertices: expected numbers, got a bool array$"),
        ([[True, 0.5, 0.5]] + v[1:].tolist(), r"^cells\[0\]: vertices: expected numbers, got True$"),
        ([["0.5", 0.5, 0.5]] + v[1:].tolist(), r"^cells\[0\]: vertices: expected numbers, got '0.5'$"),
        (np.vstack([[np.nan, 0, 0], v[1:]]), r"^cells\[0\]: vertices: vertex 0 is not finite: \[nan, 0.0, 0.0\]$"),
        # An int beyond the doubles: that vertex named, not the first.
        (v[:2].tolist() + [[10**400, 0, 0]] + v[3:].tolist(), r"^cells\[0\]: vertices: vertex 2 is not finite: \[inf, "),
        # Ragged rows given by a generator (walked once: the message still has the rows).
        ((r for r in [list(v[0][:2])] + v[1:].tolist()), r"^cells\[0\]: vertices must be \(k, 3\), got rows of 2, 3"),
    ]:
        cells = _damaged(pts, vd, lambda s, _, f, n: (s, bad, f, n))
        with pytest.raises(ValueError, match=message):
            dtlab.check_voronoi(pts, cells, box=vd.box)
    cells = _damaged(pts, vd, lambda s, _, f, n: (s, None, f, n))
    with pytest.raises(TypeError, match=r"^cells\[0\]: vertices: expected a \(k, 3\) array of numbers, got None$"):
        dtlab.check_voronoi(pts, cells, box=vd.box)
    # Nested lists, tuples and a list of rows are (k, 3) as well.
    for good in (v.tolist(), tuple(map(tuple, v.tolist())), list(v)):
        cells = _damaged(pts, vd, lambda s, _, f, n: (s, good, f, n))
        assert dtlab.check_voronoi(pts, cells, box=vd.box)["verdict"] == "exact-topology"


def test_cells_of_the_wrong_type_or_shape_name_cells():
    # cells=None raised "'NoneType' object is not iterable", a dict "too many values to
    # unpack (expected 4)" (probe 6, find 6).
    pts = np.random.default_rng(9).random((30, 3))
    vd = dtlab.voronoi(pts)
    for bad in (None, {"cells": []}, "cells", 3):
        with pytest.raises(TypeError, match=r"^cells: expected a dtlab VoronoiDiagram, a scipy.spatial.Voronoi or a "
                                            r"list of \(site, vertices, faces, face neighbours\), got "):
            dtlab.check_voronoi(pts, bad, box=vd.box)
    c = vd.cells[0]
    for bad, error, message in [
        (None, TypeError, r"^cells\[0\]: expected a \(site, vertices, faces, face neighbours\) tuple, got None$"),
        ({"site": 0}, TypeError, r"^cells\[0\]: expected a \(site, vertices, faces, face neighbours\) tuple"),
        (c, TypeError, r"^cells\[0\]: expected a \(site, vertices, faces, face neighbours\) tuple"),
        ((c.site, c.vertices, c.faces), ValueError,
         r"^cells\[0\]: expected \(site, vertices, faces, face neighbours\), got 3 items$"),
        ((c.site, c.vertices, None, c.face_neighbors), TypeError, r"^cells\[0\]: faces: expected a sequence of faces"),
        ((c.site, c.vertices, c.faces, None), TypeError,
         r"^cells\[0\]: neighbours: expected a sequence of integer ids"),
        ((c.site, c.vertices, [3] + c.faces[1:], c.face_neighbors), TypeError, r"^cells\[0\]: face 0: expected a seq"),
    ]:
        with pytest.raises(error, match=message):
            dtlab.check_voronoi(pts, [bad], box=vd.box)
    # The documented forms: the diagram, a list or a tuple of tuples or lists, a generator.
    as_tuples = [(c.site, c.vertices, c.faces, c.face_neighbors) for c in vd.cells]
    for good in (vd, as_tuples, tuple(as_tuples), [list(t) for t in as_tuples], (t for t in as_tuples)):
        assert dtlab.check_voronoi(pts, good, box=vd.box)["verdict"] == "exact-topology"
