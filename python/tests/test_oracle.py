import json
import shutil

import numpy as np
import pytest

import dtlab
from conftest import write_xyz


def test_agrees_with_cgal_and_tetgen(uniform):
    against = ["cgal"] + (["tetgen"] if shutil.which("tetgen") else [])
    r = dtlab.oracle(uniform, against=against)
    assert r.ok and r.problems == []
    assert list(r.runs) == ["dtlab"] + against
    for run in r.runs.values():
        assert run.answered and run.check.ok and run.tets.shape[1] == 4
    c = r.comparisons["dtlab vs cgal"]
    assert c.verdict == "identical" and c.detail == "agree (general position: identical tets)"
    # CGAL's cells, as the oracle returns them, have dtlab's orientation.
    assert dtlab.check(uniform, r.runs["cgal"].tets, orientation="positive").ok


def test_missing_tetgen_is_no_answer(uniform):
    r = dtlab.oracle(uniform, against="tetgen", tetgen="/nonexistent/tetgen")
    assert r.ok and not r.runs["tetgen"].answered and r.runs["tetgen"].note
    assert r.comparisons == {}


def test_same_verdicts_as_the_cli(tmp_path, cli):
    for family, index in (("cospherical", 0), ("lattice", 1), ("near_degenerate", 2), ("uniform", 0)):
        pts = dtlab.fuzz.case(family, index)
        path = write_xyz(tmp_path / f"{family}.xyz", pts)
        for predicates, perturb in (("adaptive", "sos"), ("naive", "none"), ("exact", "none")):
            args = ["oracle", path, "--against", "cgal", "--predicates", predicates, "--perturb", perturb, "--json"]
            proc = cli(*args)
            j = json.loads(proc.stdout)
            r = dtlab.oracle(pts, against=["cgal"], predicates=predicates, perturb=perturb)
            assert r.ok == j["ok"] and r.problems == j["problems"], (family, predicates, perturb)
            assert proc.returncode == (0 if r.ok else 1)
            for name, run in r.runs.items():
                assert run.answered == j["runs"][name]["answered"]
                if run.check is not None:
                    assert run.check.ok == j["runs"][name]["check"]["valid"]
                    assert run.check.stats["tets"] == j["runs"][name]["check"]["tets"]
            for pair, c in r.comparisons.items():
                cj = j["comparisons"][pair]
                assert (c.tets_equal, c.complexes_equal) == (cj["tets_equal"], cj["complexes_equal"])
