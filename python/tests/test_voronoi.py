import json

import numpy as np
import pytest

import dtlab
from conftest import write_xyz


def test_cells_tile_the_box(uniform):
    vd = dtlab.voronoi(uniform, threads=1)
    lo, hi = np.array(vd.box[0]), np.array(vd.box[1])
    assert np.allclose(lo, uniform.min(axis=0) - 0.1 * (uniform.max(axis=0) - uniform.min(axis=0)))
    assert len(vd.cells) == len(uniform)
    total = sum(c.volume for c in vd.cells)
    assert abs(total - np.prod(hi - lo)) <= 1e-12 * np.prod(hi - lo)
    for c in vd.cells:
        assert c.vertices.shape[1] == 3 and len(c.faces) == len(c.face_neighbors) >= 4
        # closed: every edge is used once in each direction
        edges = {(int(f[k]), int(f[(k + 1) % len(f)])) for f in c.faces for k in range(len(f))}
        assert all((b, a) in edges for a, b in edges)
        assert np.all(c.vertices >= lo - 1e-12) and np.all(c.vertices <= hi + 1e-12)
        assert set(c.neighbors.tolist()) == {int(n) for n in c.face_neighbors if n >= 0}
    for i, c in enumerate(vd.cells):  # neighbourhood is symmetric
        for j in c.neighbors:
            assert i in vd.cells[j].neighbors


def test_arrays_are_read_only_views(uniform):
    vd = dtlab.voronoi(uniform)
    c = vd.cells[0]
    assert not c.vertices.flags.writeable and not c.vertices.flags.owndata
    with pytest.raises(ValueError):
        c.vertices[0, 0] = 1.0
    del vd  # the views keep the diagram's storage alive
    assert np.isfinite(c.vertices).all() and c.volume > 0


def test_box_and_duplicates():
    pts = np.random.default_rng(4).random((40, 3))
    pts = np.vstack([pts, pts[:1]])
    vd = dtlab.voronoi(pts, box=((0, 0, 0), (1, 1, 1)))
    assert vd.box == ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))
    assert abs(sum(c.volume for c in vd.cells) - 1) < 1e-12
    assert vd.cells[40].duplicate_of == 0 and vd.cells[40].volume == 0 and vd.cells[40].faces == []
    assert dtlab.voronoi(pts, box=[0, 0, 0, 1, 1, 1]).box == vd.box


def test_same_cells_as_the_cli(tmp_path, uniform, cli):
    path = write_xyz(tmp_path / "u.xyz", uniform)
    j = json.loads(cli("voronoi", path, "--json").stdout)
    vd = dtlab.voronoi(uniform)
    assert len(j["cells"]) == len(vd.cells)
    for cj, c in zip(j["cells"], vd.cells):
        assert cj["volume"] == pytest.approx(c.volume, rel=1e-12)
        assert sorted(cj["neighbors"]) == c.neighbors.tolist()
