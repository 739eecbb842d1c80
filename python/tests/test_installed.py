"""Run by python:install (install_from_clean_copy.sh) next to the spatial, example and
notebook tests: proves they ran against the installed package, not the source tree."""
import os
import sys

import pytest

import dtlab


def test_dtlab_is_the_installed_one():
    venv = os.environ.get("DTLAB_EXPECT_INSTALLED")
    if not venv:
        pytest.skip("only meaningful under python:install (DTLAB_EXPECT_INSTALLED unset)")
    assert os.path.realpath(dtlab.__file__).startswith(os.path.realpath(venv)), dtlab.__file__
    assert os.path.realpath(sys.prefix) == os.path.realpath(venv)
