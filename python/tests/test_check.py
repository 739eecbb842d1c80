import itertools

import numpy as np
import pytest

import dtlab

CUBE = np.array(list(itertools.product([0.0, 1.0], repeat=3)))  # 8 cospherical points
# Two Delaunay tetrahedralizations of the cube (all 8 corners lie on one sphere):
# five tets (a central one and four corners) and six tets around the diagonal 0-7.
CUBE_5 = np.array([[0, 3, 5, 6], [0, 1, 3, 5], [0, 2, 3, 6], [0, 4, 5, 6], [3, 5, 6, 7]])
CUBE_6 = np.array([[0, 7, 1, 3], [0, 7, 3, 2], [0, 7, 2, 6], [0, 7, 6, 4], [0, 7, 4, 5], [0, 7, 5, 1]])


def test_valid_and_every_kind_counted(uniform):
    dt = dtlab.tetrahedralize(uniform)
    r = dtlab.check(uniform, dt.tets)
    assert r.ok and r.verdict == "valid Delaunay tetrahedralization"
    assert set(r.counts) == set(dtlab.DEFECT_KINDS) and not any(r.counts.values())
    assert r.defects == [] and r.stats["tets"] == len(dt.tets) and r.stats["euler"] == 1
    assert r.swapped == 0


def test_orientations(uniform):
    tets = dtlab.tetrahedralize(uniform).tets.astype(np.int64)
    swapped = tets[:, [1, 0, 2, 3]]  # TetGen's / CGAL's native handedness
    assert dtlab.check(uniform, tets, orientation="positive").ok
    neg = dtlab.check(uniform, swapped, orientation="positive")
    assert not neg.ok and neg.counts["inverted"] == len(tets)
    assert dtlab.check(uniform, swapped, orientation="negative").ok
    r = dtlab.check(uniform, swapped, orientation="consistent")
    assert r.ok and r.orientation == "negative" and r.swapped == len(tets)
    # Mixed handedness: "consistent" names the minority inverted, "any" accepts it.
    mixed = tets.copy()
    mixed[::3] = swapped[::3]
    r = dtlab.check(uniform, mixed, orientation="consistent")
    assert r.orientation == "positive" and r.counts["inverted"] == len(tets[::3])
    r = dtlab.check(uniform, mixed)
    assert r.ok and r.orientation == "any" and r.swapped == len(tets[::3])


def test_defects_with_witnesses(uniform):
    tets = dtlab.tetrahedralize(uniform).tets
    r = dtlab.check(uniform, tets[1:])  # a tet missing: a hole
    assert not r.ok and r.verdict.startswith("DEFECTS FOUND")
    assert sum(r.counts.values()) > 0 and r.defects
    assert all(d.kind in dtlab.DEFECT_KINDS for d in r.defects)
    # Moving a point keeps the mesh a tetrahedralization but no longer Delaunay (or flat/inverted).
    moved = uniform.copy()
    v = tets[0, 0]
    moved[v] += 0.05
    r = dtlab.check(moved, tets)
    assert not r.ok


def test_witness_limit(uniform):
    tets = dtlab.tetrahedralize(uniform).tets[:, [1, 0, 2, 3]]
    r = dtlab.check(uniform, tets, orientation="positive", witnesses=3)
    assert r.counts["inverted"] == len(tets)
    assert sum(d.kind == "inverted" for d in r.defects) == 3


def test_cospherical_cube():
    for tets in (CUBE_5, CUBE_6):
        r = dtlab.check(CUBE, tets)
        assert r.ok, r.verdict
        assert r.stats["cospherical_facets"] > 0
    c = dtlab.compare(CUBE, CUBE_5, CUBE_6)
    assert c.verdict == "same Delaunay complex" and c.complexes_equal and not c.tets_equal
    assert c.cells == (1, 1) and c.general_position is False
    assert "tets differ inside cospherical cells" in c.detail


def test_compare(uniform):
    a = dtlab.tetrahedralize(uniform).tets
    b = dtlab.tetrahedralize(uniform, predicates="exact", order="input", seed=4).tets
    rng = np.random.default_rng(0)
    b = b[rng.permutation(len(b))][:, [2, 0, 1, 3]]  # another order and handedness
    c = dtlab.compare(uniform, a, b)
    assert c.verdict == "identical" and c.general_position and c.a.ok and c.b.ok
    assert c.detail == "agree (general position: identical tets)"
    c = dtlab.compare(uniform, a, a[1:])
    assert c.verdict == "different" and c.complexes_equal is None and not c.b.ok
    assert "second mesh is not a valid" in c.detail
    assert dtlab.compare(uniform, a[1:], a[1:]).verdict == "identical"


def test_scipy_output_checks_as_it_comes(uniform):
    spatial = pytest.importorskip("scipy.spatial")
    simplices = spatial.Delaunay(uniform).simplices
    r = dtlab.check(uniform, simplices)
    assert r.ok and 0 < r.swapped < len(simplices)  # scipy's 3D simplices come in both orders
    assert dtlab.compare(uniform, simplices, dtlab.tetrahedralize(uniform).tets).verdict == "identical"


def test_any_integer_dtype(uniform):
    tets = dtlab.tetrahedralize(uniform).tets
    for dtype in (np.int32, np.int64, np.uint16, np.uint64):
        assert dtlab.check(uniform, tets.astype(dtype)).ok
    assert dtlab.check(uniform.tolist(), tets.tolist()).ok


def test_threads_give_the_serial_report(uniform):
    dt = dtlab.tetrahedralize(uniform)
    broken = dt.tets.copy()
    broken[3, [0, 1]] = broken[3, [1, 0]]  # one inverted tet
    broken = broken[5:]                     # and a hole
    for tets in (dt.tets, broken):
        serial = dtlab.check(uniform, tets, "positive", witnesses=100)
        for threads in (0, 2, 3):
            r = dtlab.check(uniform, tets, "positive", witnesses=100, threads=threads)
            assert r.counts == serial.counts and r.stats["edges"] == serial.stats["edges"]
            assert [(d.kind, d.tets, d.vertices) for d in r.defects] == \
                [(d.kind, d.tets, d.vertices) for d in serial.defects]
    with pytest.raises(ValueError, match="threads"):
        dtlab.check(uniform, dt.tets, threads=-1)
