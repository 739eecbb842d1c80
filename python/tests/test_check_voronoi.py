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
        ((site, verts, [[-1, 0, 1]] + faces[1:], nbrs), "face 0: -1 is below 0"),
        ((site, verts, [[0, 1, len(verts)]] + faces[1:], nbrs), "out of range"),
        ((0.5, verts, faces, nbrs), "site: expected integer ids"),
        ((site, verts, faces, np.asarray(nbrs, dtype=np.float64)), "neighbours: expected integer ids"),
        ((site, verts, faces, [-7] * len(nbrs)), "neighbours: -7 is below -6"),
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
