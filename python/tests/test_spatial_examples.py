"""The scipy-to-dtlab examples: a scipy 3D script runs unchanged but for the import and
prints the same on general-position points; the walkthrough proves dtlab's answer."""
import os
import subprocess
import sys

import pytest

pytest.importorskip("scipy.spatial", reason="scipy is not installed (Debian: python3-scipy): examples skipped")
EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "examples")
IMPORT = "from scipy.spatial import ConvexHull, Delaunay, Voronoi"


def run(path, *args):
    r = subprocess.run([sys.executable, path, *map(str, args)], capture_output=True, text=True, timeout=240)
    assert r.returncode == 0, r.stdout + r.stderr
    return dict(line.split(":", 1) if ":" in line else (line, "") for line in r.stdout.splitlines())


@pytest.fixture(scope="module")
def dtlab_script(tmp_path_factory):
    text = open(os.path.join(EXAMPLES, "scipy_3d_script.py")).read()
    assert text.count("\n" + IMPORT + "\n") == 1
    path = tmp_path_factory.mktemp("ex") / "dtlab_3d_script.py"
    path.write_text(text.replace("\n" + IMPORT + "\n", "\nfrom dtlab.spatial import ConvexHull, Delaunay, Voronoi\n"))
    return str(path)


def test_scipy_script_unchanged_but_for_the_import(dtlab_script):
    theirs = run(os.path.join(EXAMPLES, "scipy_3d_script.py"), "uniform", 1000)
    ours = run(dtlab_script, "uniform", 1000)
    assert set(ours) == set(theirs) and len(ours) == 6
    for key in ours:
        if key != "interpolation error":  # the last bits differ: the vertex order of each tet does
            assert ours[key] == theirs[key], key
    assert float(ours["interpolation error"]) < 1e-12


def test_scipy_script_on_a_lattice(dtlab_script):
    ours = run(dtlab_script, "lattice", 1000)
    assert ours["simplices"].strip() == "4374"  # 9^3 cubes, 6 tets each: scipy's has more (overlapping)
    assert float(ours["interpolation error"]) < 1e-12
    assert "hull volume 729, area 486, vertices 8" in ours  # the cube's 8 corners, as scipy's


def test_walkthrough_proves_dtlab():
    out = run(os.path.join(EXAMPLES, "scipy_to_dtlab.py"), 6)
    assert "DEFECTS FOUND" in out["scipy.spatial.Delaunay"]
    assert "valid Delaunay tetrahedralization" in out["dtlab.spatial.Delaunay"]
    assert "125 vertices (cubes: 125)" in out["dtlab.spatial.Voronoi"]
