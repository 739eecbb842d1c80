"""scipy's own tests (scipy/spatial/tests/test_qhull.py of Debian's python3-scipy), run
against dtlab.spatial: the module is loaded from the installed file and its `qhull` and
`Voronoi` names are pointed at dtlab's classes. Only the tests that apply to 3D run
(python/README.md lists them; 2D, n-D, furthest-site, Qhull-option and Qhull-internal
tests do not apply); nothing of scipy's is copied here."""
import importlib.util
import os
import types

import numpy as np
import pytest

from dtlab import spatial

pytestmark = pytest.mark.filterwarnings("ignore::pytest.PytestUnknownMarkWarning")  # scipy's "slow"

scipy = pytest.importorskip("scipy", reason="scipy (python3-scipy) is not installed")
PATH = os.path.join(os.path.dirname(scipy.__file__), "spatial", "tests", "test_qhull.py")
if not os.path.exists(PATH):
    pytest.skip(f"scipy's tests are not installed ({PATH})", allow_module_level=True)


@pytest.fixture(scope="module")
def tq():
    spec = importlib.util.spec_from_file_location("scipy_test_qhull", PATH)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    mod.qhull = types.SimpleNamespace(Delaunay=spatial.Delaunay, ConvexHull=spatial.ConvexHull,
                                      Voronoi=spatial.Voronoi)
    mod.Voronoi = spatial.Voronoi
    return mod


# (class, test, arguments): scipy's whole tests that are 3D (or dimension-free).
WHOLE = [
    ("TestUtilities", "test_volume_area", ()),
    ("TestUtilities", "test_random_volume_area", ()),
    ("TestUtilities", "test_incremental_volume_area_random_input", ()),
    ("TestDelaunay", "test_masked_array_fails", ()),
    ("TestConvexHull", "test_masked_array_fails", ()),
    ("TestConvexHull", "test_volume_area", ()),
    ("TestConvexHull", "test_hull_consistency_tri", ("random-3d",)),
    ("TestVoronoi", "test_masked_array_fails", ()),
    ("TestVoronoi", "test_ridges", ("random-3d",)),
    ("TestVoronoi", "test_point_region_structure", ("Qbb Qc", 50, 0, 3)),
    ("TestVoronoi", "test_point_region_structure", ("Qbb Qc", 100, 0, 3)),
] + [("TestDelaunay", "test_incremental", (f"random-3d-chunk-{c}",)) for c in (1, 4, 16)] \
  + [("TestConvexHull", "test_incremental", (f"random-3d-chunk-{c}",)) for c in (1, 4, 16)] \
  + [("TestVoronoi", "test_incremental", (f"random-3d-chunk-{c}",)) for c in (1, 4, 16)]


@pytest.mark.parametrize("cls,name,args", WHOLE, ids=[f"{c}.{n}{list(a)}" for c, n, a in WHOLE])
def test_scipy_test(tq, cls, name, args):
    getattr(getattr(tq, cls)(), name)(*args)


def grid(n):
    x = np.linspace(0, 1, n)
    return np.stack(np.meshgrid(x, x, x, indexing="ij"), -1).reshape(-1, 3)


def test_more_barycentric_transforms_3d(tq):
    """The 3D case of TestUtilities.test_more_barycentric_transforms (scipy runs 2-5D in
    one test): its check on the 11^3 grid, the grid with 2-eps jitter and the grid twice."""
    t = tq.TestUtilities()
    g = grid(11)
    t._check_barycentric_transforms(spatial.Delaunay(g), err_msg="ndim=3", unit_cube=True)
    rng = np.random.RandomState(1234)
    eps = np.finfo(float).eps
    m = rng.rand(len(g)) < 0.2
    g[m] += 2 * eps * (rng.rand(*g[m].shape) - 0.5)
    t._check_barycentric_transforms(spatial.Delaunay(g), err_msg="ndim=3", unit_cube=True, unit_cube_tol=2 * eps)
    t._check_barycentric_transforms(spatial.Delaunay(np.r_[g, g]), err_msg="ndim=3", unit_cube=True,
                                    unit_cube_tol=2 * eps)


@pytest.mark.parametrize("points", ["random-3d", "grid", "simplex"])
def test_vertex_neighbor_vertices_3d(tq, points):
    """TestVertexNeighborVertices._check (scipy applies it to 2D sets) on 3D ones."""
    pts = {"random-3d": tq.DATASETS["random-3d"], "grid": grid(4),
           "simplex": np.array([[1.0, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]])}[points]
    tq.TestVertexNeighborVertices()._check(spatial.Delaunay(pts))


def test_nd_simplex_3d():
    """The 3D case of TestDelaunay.test_nd_simplex: one simplex, no neighbours."""
    pts = np.array([[1.0, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]])
    tri = spatial.Delaunay(pts)
    assert (np.sort(tri.simplices, axis=1) == [[0, 1, 2, 3]]).all() and (tri.neighbors == -1).all()
