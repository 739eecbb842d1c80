"""examples/scipy_to_dtlab.ipynb: valid nbformat 4 (checked by nbformat when installed),
and its code cells run in order, in one namespace, as a kernel would run them (no
Jupyter kernel needed); then what it claims holds: scipy's grid tets have defects,
dtlab's are proven the Delaunay tetrahedralization."""
import contextlib
import io
import json
import os

import pytest

NOTEBOOK = os.path.join(os.path.dirname(__file__), "..", "examples", "scipy_to_dtlab.ipynb")


def load():
    with open(NOTEBOOK, encoding="utf-8") as f:
        return json.load(f)


def test_notebook_is_nbformat_4():
    nb = load()
    assert nb["nbformat"] == 4
    assert all(c["cell_type"] in ("markdown", "code") for c in nb["cells"])
    nbformat = pytest.importorskip("nbformat", reason="python3-nbformat not installed")
    nbformat.validate(nbformat.reads(json.dumps(nb), as_version=4))


def test_notebook_runs_and_proves():
    pytest.importorskip("scipy", reason="python3-scipy not installed")
    ns = {"__name__": "__main__"}
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        for i, cell in enumerate(load()["cells"]):
            if cell["cell_type"] == "code":
                exec(compile("".join(cell["source"]), f"{NOTEBOOK}:cell {i}", "exec"), ns)
    text = out.getvalue()
    assert not ns["scipy_report"].ok and "DEFECTS FOUND" in text
    assert ns["proof"].ok and ns["report"].ok
    assert ns["proof"].stats["cover_proven"]
    assert ns["total_volume"](ns["tri"].simplices) == pytest.approx((ns["k"] - 1) ** 3, rel=1e-12)
    assert ns["seen"][0] == ("insert", 0, len(ns["grid"])) and ns["seen"][-1] == ("check", 8, 8)
