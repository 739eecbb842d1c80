import json
import shutil

import pytest

import dtlab
from conftest import write_xyz


def test_agrees_with_cgal_and_tetgen(uniform):
    against = ["cgal"] + (["tetgen"] if shutil.which("tetgen") else [])
    r = dtlab.oracle(uniform, against=against)
    assert r.ok and r.exit == 0 and r.problems == [] and r.not_compared == []
    assert list(r.peers) == against
    assert r.dtlab.verdict == "delaunay" and r.dtlab.check.ok
    for run in r.peers.values():
        assert run.verdict == "delaunay" and run.agree is True and run.tets.shape[1] == 4
    c = r.comparisons["dtlab vs cgal"]
    assert c.verdict == "identical" and c.detail == "agree (general position: identical tets)"
    # A peer's tets, as the oracle returns them, have dtlab's orientation.
    assert dtlab.check(uniform, r.peers["cgal"].tets, orientation="positive").ok


def test_kernel_options_reach_our_build(uniform):
    # The thesis's enclosing tet with a factor too small drops hull tets: ours is wrong,
    # the peer is not (the same call with the defaults agrees, above).
    r = dtlab.oracle(uniform, against=["cgal"], boundary="bigtet:1", order="input", seed=5)
    assert not r.ok and r.exit == 1
    assert r.dtlab.verdict != "delaunay" and r.peers["cgal"].verdict == "delaunay"
    with pytest.raises(ValueError):
        dtlab.oracle(uniform, against=["cgal"], order="sideways")


def test_missing_peer_is_no_answer(uniform):
    r = dtlab.oracle(uniform, against="tetgen", tetgen="/nonexistent/tetgen")
    assert not r.ok and r.exit == 3 and r.problems == []
    assert r.peers["tetgen"].verdict == "not-installed" and r.peers["tetgen"].tets is None
    assert r.comparisons == {} and r.not_compared == ["tetgen (not-installed)"]


def test_bad_arguments(uniform):
    with pytest.raises(ValueError, match="against"):
        dtlab.oracle(uniform, against=["no-such-peer"])
    with pytest.raises(ValueError, match="timeout"):
        dtlab.oracle(uniform, against=["cgal"], timeout=float("nan"))
    with pytest.raises(ValueError):
        dtlab.oracle(uniform[:3], against=["cgal"])


def test_same_verdicts_as_the_cli(tmp_path, cli):
    for family, index in (("cospherical", 0), ("lattice", 1), ("near_degenerate", 2), ("uniform", 0)):
        pts = dtlab.fuzz.case(family, index)
        path = write_xyz(tmp_path / f"{family}.xyz", pts)
        for predicates, perturb in (("adaptive", "sos"), ("naive", "none"), ("exact", "none")):
            args = ["oracle", path, "--against", "cgal", "--predicates", predicates, "--perturb", perturb, "--json"]
            proc = cli(*args)
            j = json.loads(proc.stdout)
            r = dtlab.oracle(pts, against=["cgal"], predicates=predicates, perturb=perturb)
            assert (r.ok, r.exit, r.problems) == (j["ok"], j["exit"], j["problems"]), (family, predicates, perturb)
            assert proc.returncode == r.exit
            assert r.dtlab.verdict == j["dtlab"]["verdict"]
            assert r.dtlab.check.ok == j["dtlab"]["check"]["valid"]
            for name, run in r.peers.items():
                assert run.verdict == j["peers"][name]["verdict"]
                assert run.agree == j["peers"][name].get("agree")
            assert set(r.comparisons) == set(j["comparisons"])
            for pair, c in r.comparisons.items():
                cj = j["comparisons"][pair]
                assert (c.tets_equal, c.complexes_equal) == (cj["tets_equal"], cj["complexes_equal"])
