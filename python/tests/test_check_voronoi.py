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
