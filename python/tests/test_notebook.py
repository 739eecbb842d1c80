"""The example notebook (python/examples/scipy_to_dtlab.ipynb) runs: its code cells are
executed in order in one namespace, as a kernel would, and the claims its text makes are
checked on the results. nbformat's schema check runs when python3-nbformat is installed."""
import json
import os

import pytest

NOTEBOOK = os.path.join(os.path.dirname(__file__), "..", "examples", "scipy_to_dtlab.ipynb")


def load_notebook():
    with open(NOTEBOOK, encoding="utf-8") as f:
        return json.load(f)


def test_notebook_is_nbformat_4():
    nb = load_notebook()
    assert nb["nbformat"] == 4
    kinds = [c["cell_type"] for c in nb["cells"]]
    assert kinds.count("code") >= 4 and kinds.count("markdown") >= 4
    for cell in nb["cells"]:
        if cell["cell_type"] == "code":
            assert cell["outputs"] == [] and cell["execution_count"] is None, "commit the notebook without outputs"
    try:
        import nbformat
    except ImportError:
        return
    nbformat.validate(nbformat.reads(json.dumps(nb), as_version=4))


def test_notebook_cells_run_and_its_claims_hold():
    pytest.importorskip("scipy.spatial", reason="scipy is not installed (Debian: python3-scipy)")
    namespace = {"__name__": "__notebook__"}
    for i, cell in enumerate(load_notebook()["cells"]):
        if cell["cell_type"] == "code":
            exec(compile("".join(cell["source"]), f"{NOTEBOOK}:cell {i}", "exec"), namespace)
    k = namespace["k"]
    cube = (k - 1) ** 3
    # scipy's answer on the grid is not a tetrahedralization; the notebook says so.
    assert not namespace["scipy_report"].ok
    assert namespace["scipy_flat"].sum() > 0
    # dtlab's is, proven; its tets tile the cube exactly once.
    assert namespace["dtlab_report"].ok
    tri = namespace["tri"]
    assert namespace["tet_volumes"](namespace["grid"], tri.simplices).sum() == pytest.approx(cube, rel=1e-12)
    assert (namespace["tet_volumes"](namespace["grid"], tri.simplices) > 0).all()
    assert namespace["outside"] == 0
    # one Voronoi vertex per cube of eight cospherical corners
    assert len(namespace["vor"].vertices) == cube
