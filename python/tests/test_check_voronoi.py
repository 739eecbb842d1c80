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
