import os
import subprocess
import sys

import pytest

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "examples", "check_scipy.py")


def test_check_scipy_example_runs():
    pytest.importorskip("scipy.spatial", reason="scipy is not installed (Debian: python3-scipy): example skipped")
    r = subprocess.run([sys.executable, EXAMPLE, "--points", "300", "--families", "uniform,lattice,cospherical"],
                       capture_output=True, text=True, timeout=240)
    assert r.returncode == 0, r.stdout + r.stderr
    lines = r.stdout.splitlines()
    rows = {line.split()[0]: line for line in lines[1:]}
    assert set(rows) == {"uniform", "lattice", "cospherical", "mesh:winding", "mesh:surface"}
    assert "scipy vs dtlab: identical" in rows["uniform"]
    for line in rows.values():
        assert "dtlab" in line and "valid" in line
