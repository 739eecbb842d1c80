import glob
import json
import os

import numpy as np
import pytest

import dtlab
from conftest import read_node


def test_families_match_the_cli_list(cli):
    fams = dtlab.fuzz.families()
    lines = cli("fuzz", "--list").stdout.splitlines()
    assert list(fams) == [line.split()[0] for line in lines]
    for line in lines:
        name = line.split()[0]
        assert line[len(name):].strip() == fams[name]


def test_generate_is_reproducible():
    for name in dtlab.fuzz.families():
        a = dtlab.fuzz.generate(name, 40, 11)
        assert a.shape == (40, 3) and a.dtype == np.float64
        assert np.array_equal(a, dtlab.fuzz.generate(name, 40, 11))
        assert np.isfinite(a).all()
    assert not np.array_equal(dtlab.fuzz.generate("uniform", 40, 1), dtlab.fuzz.generate("uniform", 40, 2))


def test_bit_identical_to_the_cli_campaign(tmp_path, cli):
    # An epsilon band of 1e300 calls every input flat, so every 3D case fails and, with a
    # shrink budget of 0, the campaign stores each case's points unshrunk in its corpus.
    out = tmp_path / "camp"
    cli("fuzz", "--family", "all", "--cases", 2, "--seed", 5, "--predicates", "epsilon", "--eps", "1e300",
        "--perturb", "none", "--shrink-budget", 0, "--jobs", 1, "--out", out)
    entries = sorted(glob.glob(str(out / "corpus" / "*.json")))
    families = set()
    for e in entries:
        with open(e) as f:
            j = json.load(f)
        assert j["points"] == j["points_original"]
        cli_points = read_node(os.path.splitext(e)[0] + ".node")
        seed = dtlab.fuzz.case_seed(5, j["family"], j["case"])
        assert seed == j["case_seed"]
        assert dtlab.fuzz.case_points(seed) == j["points"]
        ours = dtlab.fuzz.generate(j["family"], j["points"], j["case_seed"])
        assert ours.tobytes() == cli_points.tobytes(), e  # the same bits (-0.0 and subnormals included)
        assert np.array_equal(dtlab.fuzz.case(j["family"], j["case"], seed=5), ours)
        families.add(j["family"])
    assert len(families) >= 14, sorted(families)  # all but the truly flat families


def test_bad_arguments():
    with pytest.raises(ValueError, match="seed"):
        dtlab.fuzz.generate("uniform", 10, -1)
    with pytest.raises(ValueError, match="min_points"):
        dtlab.fuzz.case_points(1, 10, 5)
