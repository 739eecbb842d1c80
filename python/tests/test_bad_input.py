"""Bad input raises ValueError (with the CLI's message where the CLI has one)."""
import numpy as np
import pytest

import dtlab

GOOD = np.random.default_rng(3).random((20, 3))
TETS = dtlab.tetrahedralize(GOOD).tets


def calls(points):
    """Every function that takes a point array, called on `points`."""
    return {
        "tetrahedralize": lambda: dtlab.tetrahedralize(points),
        "check": lambda: dtlab.check(points, TETS),
        "compare": lambda: dtlab.compare(points, TETS, TETS),
        "oracle": lambda: dtlab.oracle(points, against=["cgal"]),
        "voronoi": lambda: dtlab.voronoi(points),
    }


@pytest.mark.parametrize("name", list(calls(GOOD)))
@pytest.mark.parametrize("points,message", [
    (np.zeros((5, 2)), r"points must be an \(n, 3\) array, got shape \(5, 2\)"),
    (np.zeros(12), r"got shape \(12,\)"),
    (np.zeros((2, 3, 3)), r"got shape \(2, 3, 3\)"),
    (np.array([["a", "b", "c"]]), "real numbers"),
    ([[0, 0, 0], [1, 0], [0, 1, 0]], "points must be an"),
])
def test_wrong_shape(name, points, message):
    with pytest.raises(ValueError, match=message):
        calls(points)[name]()


@pytest.mark.parametrize("name", list(calls(GOOD)))
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite(name, bad):
    pts = GOOD.copy()
    pts[7, 1] = bad
    with pytest.raises(ValueError, match=r"points\[7\]: non-finite coordinate"):
        calls(pts)[name]()


@pytest.mark.parametrize("name", ["tetrahedralize", "check", "compare", "oracle"])
def test_fewer_than_4_points(name):
    with pytest.raises(ValueError, match="fewer than 4 points"):
        calls(GOOD[:3])[name]()


def test_lower_dimensional_input():
    flat = GOOD.copy()
    flat[:, 2] = 0
    with pytest.raises(ValueError, match="coplanar"):
        dtlab.tetrahedralize(flat)
    with pytest.raises(ValueError, match="collinear"):
        dtlab.tetrahedralize(np.outer(np.arange(10.0), [1, 2, 3]))


@pytest.mark.parametrize("kw,message", [
    ({"predicates": "fast"}, "^predicates: fast not in"),
    ({"perturb": "yes"}, "^perturb: "),
    ({"order": "random"}, "^order: "),
    ({"boundary": "box"}, "^boundary: expected infinite or bigtet"),
    ({"boundary": "bigtet:-1"}, "^boundary: bigtet FACTOR '-1' is not in"),
    ({"eps_mode": "scaled"}, "^eps_mode: "),
    ({"seed": -1}, "^seed: "),
])
def test_bad_options(kw, message):
    with pytest.raises(ValueError, match=message):
        dtlab.tetrahedralize(GOOD, **kw)


def test_bad_tets():
    with pytest.raises(ValueError, match=r"tets must be an \(m, 4\) array"):
        dtlab.check(GOOD, TETS[:, :3])
    with pytest.raises(ValueError, match=r"tets\[2, 1\]: vertex index 20 out of range \(20 points\)"):
        bad = TETS.astype(np.int64)
        bad[2, 1] = 20
        dtlab.check(GOOD, bad)
    with pytest.raises(ValueError, match="vertex index -1 out of range"):
        bad = TETS.astype(np.int64)
        bad[0, 0] = -1
        dtlab.check(GOOD, bad)
    with pytest.raises(ValueError, match="integer array"):
        dtlab.check(GOOD, TETS.astype(float))
    with pytest.raises(ValueError, match="orientation: 'left' not in"):
        dtlab.check(GOOD, TETS, orientation="left")
    with pytest.raises(ValueError, match=r"tets_b\[0, 0\]"):
        bad = TETS.astype(np.int64)
        bad[0, 0] = 99
        dtlab.compare(GOOD, TETS, bad)


def test_bad_other_arguments(tmp_path):
    with pytest.raises(ValueError, match="^against: .*'qhul'"):
        dtlab.oracle(GOOD, against=["qhul"])
    with pytest.raises(ValueError, match="^box needs"):
        dtlab.voronoi(GOOD, box=(1, 0, 0, 0, 1, 1))
    with pytest.raises(ValueError, match="no points"):
        dtlab.voronoi(np.zeros((0, 3)))
    with pytest.raises(ValueError, match="^method: "):
        dtlab.sample("builtin", 10, method="grid")
    with pytest.raises(ValueError, match="^family: unknown family 'nope'"):
        dtlab.fuzz.generate("nope", 10, 1)
    with pytest.raises(ValueError, match="mesh has no triangles"):
        dtlab.sample((GOOD, np.zeros((0, 3), dtype=np.int32)), 10)
    with pytest.raises(ValueError, match=r"faces\[0, 2\]: vertex index 20 out of range"):
        dtlab.sample((GOOD, np.array([[0, 1, 20]])), 10)
    with pytest.raises(ValueError, match="^sampler must be rays, sdf or winding"):
        dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, sampler="surface")
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n")
    with pytest.raises(ValueError, match=str(bad) + ":5: "):
        dtlab.read_mesh(bad)
    with pytest.raises(FileNotFoundError):
        dtlab.read_mesh(tmp_path / "missing.off")


@pytest.mark.parametrize("call,message", [
    (lambda: dtlab.sample("builtin", 0), r"^n: expected an integer in \[1, 1073741824\], got 0"),
    (lambda: dtlab.sample("builtin", 2**30 + 1), r"^n: expected an integer in \[1, 1073741824\]"),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=0), r"^pieces: expected an integer in \[1, 100000\]"),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, recurse_pieces=0), r"^recurse_pieces: "),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, site_noise=11), r"^site_noise: expected a number in \[0, 10\]"),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, impact=(0, 0, 0)), r"^impact needs impact_radius"),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, cell_scale=(1, 1)), r"^cell_scale: expected 3 numbers in "),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, density=0), r"^density: "),
    (lambda: dtlab.voronoi(GOOD, margin=-1), r"^margin: expected a number in \[0, 1e\+06\], got -1"),
    (lambda: dtlab.voronoi(GOOD * 1e99, margin=1000), r"^margin 1000 grows the sites' bounding box beyond 1e101"),
    (lambda: dtlab.voronoi(GOOD, box=(-1e102, 0, 0, 1, 1, 1)), r"^box: expected a number in "),
    (lambda: dtlab.voronoi(GOOD, predicates="fast"), r"^predicates: fast not in"),
    (lambda: dtlab.oracle(GOOD, against=["cgal"], timeout=0), r"^timeout: "),
    (lambda: dtlab.oracle(GOOD, against=["cgal"], memory_mb=-1), r"^memory_mb: "),
    (lambda: dtlab.tetrahedralize(GOOD, eps=-1, predicates="epsilon"), r"^eps: "),
])
def test_messages_name_the_python_parameter(call, message):
    """A bad argument's message names the parameter as the caller wrote it (pieces=,
    n=, eps_mode=), never the CLI's option (--pieces, --count, --eps-mode)."""
    with pytest.raises(ValueError, match=message) as e:
        call()
    assert "--" not in str(e.value).split(":")[0]


def test_wrapped_unsigned_index_is_explained():
    t = dtlab.tetrahedralize(GOOD).tets  # uint32
    with pytest.raises(ValueError, match=r"tets\[0, \d\]: vertex index 4294967\d{3} out of range \(20 points\) "
                       r"\(a uint32 array: -\d+ wrapped around\)"):
        dtlab.check(GOOD, t - np.uint32(100))
    with pytest.raises(ValueError, match=r"vertex index 99 out of range \(20 points\)$"):
        bad = t.astype(np.int64)
        bad[0, 0] = 99
        dtlab.check(GOOD, bad)


@pytest.mark.parametrize("call,message", [
    (lambda: dtlab.check_voronoi(GOOD, dtlab.voronoi(GOOD), vertex_tolerance=-1), r"^vertex_tolerance: "),
    (lambda: dtlab.check_voronoi(GOOD, dtlab.voronoi(GOOD), volume_tolerance=float("nan")), r"^volume_tolerance: "),
    (lambda: dtlab.check_voronoi(GOOD, dtlab.voronoi(GOOD), ulps=float("inf")), r"^ulps: "),
    (lambda: dtlab.voronoi(GOOD, margin=1e30), r"^margin: "),
    (lambda: dtlab.voronoi(GOOD, margin="x"), r"^margin: expected a number"),
    (lambda: dtlab.oracle(GOOD, against=[], seed=2.5), r"^seed: "),
    (lambda: dtlab.oracle(GOOD, against=[], seed=True), r"^seed: "),
    (lambda: dtlab.fuzz.generate("uniform", 10**13, 1), r"^n: "),
    (lambda: dtlab.tetrahedralize(GOOD, eps="x"), r"^eps: "),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, recurse=3), r"^recurse"),
    (lambda: dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=2, margin=1e6), r"^margin"),
])
def test_numbers_are_checked_as_the_cli_checks_them(call, message):
    """nan, inf, bools, strings, a float for an integer and values out of the CLI's range
    are refused naming the parameter, never truncated or silently used."""
    with pytest.raises(ValueError, match=message):
        call()


def test_campaign_out_must_be_a_folder(tmp_path):
    f = tmp_path / "afile"
    f.write_text("")
    with pytest.raises(ValueError, match=r"^out: .*is not a directory"):
        dtlab.fuzz.campaign("dtlab:adaptive", "uniform", cases=1, out=f)
