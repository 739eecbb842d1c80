"""Shared fixtures: the dtlab CLI (for bit-for-bit comparisons) and small inputs."""
import os
import shutil
import subprocess

import numpy as np
import pytest


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: left out of `make test` (the ctest entry python:FILE:slow runs them)")


@pytest.fixture(scope="session")
def cli():
    """Runs the `dtlab` binary (DTLAB_CLI, set by CTest) and returns its CompletedProcess."""
    path = os.environ.get("DTLAB_CLI") or shutil.which("dtlab")
    if not path or not os.path.exists(path):
        pytest.skip("the dtlab CLI is not built (DTLAB_CLI unset)")

    def run(*args, check=True):
        r = subprocess.run([path, *map(str, args)], capture_output=True, text=True, timeout=240)
        if check and r.returncode not in (0, 1):
            raise AssertionError(f"dtlab {' '.join(map(str, args))}: exit {r.returncode}\n{r.stderr}")
        return r

    return run


@pytest.fixture
def uniform():
    return np.random.default_rng(5).random((300, 3))


def write_xyz(path, points):
    """The CLI's .xyz format, every double round-tripping exactly (%.17g)."""
    with open(path, "w") as f:
        for p in points:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
    return str(path)


def read_node(path):
    with open(path) as f:
        n = int(f.readline().split()[0])
        return np.array([[float(x) for x in f.readline().split()[1:4]] for _ in range(n)])
