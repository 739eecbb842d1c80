import numpy as np
import pytest

import dtlab


def read_xyz(path):
    return np.loadtxt(path, dtype=np.float64, ndmin=2)


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for v in vertices:
            f.write("%.17g %.17g %.17g\n" % tuple(v))
        for t in faces:
            f.write("3 %d %d %d\n" % tuple(t))
    return path


def test_read_mesh_builtin():
    m = dtlab.read_mesh("builtin")
    assert m.vertices.shape[1] == 3 and m.faces.shape[1] == 3 and m.faces.dtype == np.uint32
    assert m.faces.max() < len(m.vertices)
    v, f = m  # a (vertices, faces) pair


def test_read_mesh_file_round_trip(tmp_path):
    v, f = dtlab.read_mesh("builtin")
    path = write_off(tmp_path / "torus.off", v, f)
    m = dtlab.read_mesh(path)
    assert np.array_equal(m.vertices, v) and np.array_equal(m.faces, f)


@pytest.mark.parametrize("method", ["winding", "sdf", "rays", "surface"])
def test_same_points_as_the_cli(tmp_path, cli, method):
    out = tmp_path / "p.xyz"
    cli("sample", "builtin", "--method", method, "--count", 500, "--seed", 3, "--out", out)
    pts = dtlab.sample("builtin", 500, method=method, seed=3)
    assert pts.shape == (500, 3) and pts.dtype == np.float64
    assert np.array_equal(pts, read_xyz(out))  # bit for bit (%.17g round-trips)


def test_arrays_path_and_builtin_agree(tmp_path):
    v, f = dtlab.read_mesh("builtin")
    path = write_off(tmp_path / "torus.off", v, f)
    a = dtlab.sample("builtin", 300, seed=5)
    assert np.array_equal(a, dtlab.sample((v, f), 300, seed=5))
    assert np.array_equal(a, dtlab.sample(path, 300, seed=5))
    assert np.array_equal(a, dtlab.sample(str(path), 300, seed=5))
    assert not np.array_equal(a, dtlab.sample("builtin", 300, seed=6))


def test_blue_noise_and_inside():
    v, f = dtlab.read_mesh("builtin")
    pts = dtlab.sample((v, f), 400, blue_noise=True, seed=2)
    assert pts.shape == (400, 3)
    # every sample of the torus (major 1, tube <= 0.5) lies within its bounds
    r = np.hypot(pts[:, 0], pts[:, 1])
    assert np.all(np.abs(pts[:, 2]) <= 0.5) and np.all((r >= 0.5) & (r <= 1.5))


def test_flat_mesh_has_no_inside():
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
    f = np.array([[0, 1, 2], [1, 3, 2]])
    with pytest.raises(ValueError, match="mesh encloses little volume"):
        dtlab.sample((v, f), 10)
    assert dtlab.sample((v, f), 10, method="surface").shape == (10, 3)
