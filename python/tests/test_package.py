"""The package's surface: the stubs describe _core, __all__ is importable, docstrings exist."""
import ast
import inspect
import os
import re

import dtlab
from dtlab import _core


def test_stubs_match_the_compiled_module():
    path = os.path.join(os.path.dirname(dtlab.__file__), "_core.pyi")
    tree = ast.parse(open(path).read())
    stubbed = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    stubbed |= {n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)}
    public = {n for n in dir(_core) if not n.startswith("_")} | {"__version__"}
    assert stubbed == public
    for n in tree.body:
        if isinstance(n, ast.FunctionDef):
            sig = getattr(_core, n.name).__doc__.splitlines()[0]  # pybind11: "name(a: T, ...) -> R"
            assert sig.startswith(n.name + "(")
            args = re.findall(r"(\w+):", sig[sig.index("(") + 1:sig.rindex(")")])
            assert args == [a.arg for a in n.args.args], (n.name, sig)
    assert os.path.exists(os.path.join(os.path.dirname(dtlab.__file__), "py.typed"))


def test_public_api_is_documented():
    for name in dtlab.__all__:
        obj = getattr(dtlab, name)
        if callable(obj) or inspect.ismodule(obj):
            assert obj.__doc__ and len(obj.__doc__) > 40, name
    for f in (dtlab.fuzz.families, dtlab.fuzz.generate, dtlab.fuzz.case):
        assert f.__doc__
