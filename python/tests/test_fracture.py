import numpy as np
import pytest

import dtlab


def edges_closed(faces):
    e = {(int(t[k]), int(t[(k + 1) % 3])) for t in faces for k in range(3)}
    return all((b, a) in e for a, b in e)


def test_builtin_torus_into_closed_pieces():
    v, f = dtlab.read_mesh("builtin")
    pieces = dtlab.fracture(v, f, pieces=6, seed=2, threads=2)
    assert isinstance(pieces, list) and len(pieces) == 6
    assert pieces.relative_volume_error < 1e-9
    assert sum(p.volume for p in pieces) == pytest.approx(pieces.mesh_volume, rel=1e-9)
    for i, p in enumerate(pieces):
        assert p.volume > 0 and p.faces.shape[1] == 3 and p.vertices.shape[1] == 3
        assert p.cut.dtype == bool and p.cut.shape == (len(p.faces),) and p.cut.any() and not p.cut.all()
        assert edges_closed(p.faces)
        for j in p.neighbors:
            assert i in pieces[j].neighbors
    assert pieces.manifest["pieces"][0]["volume"] == pieces[0].volume


def test_margin_loses_volume_and_recursion():
    v, f = dtlab.read_mesh("builtin")
    pieces = dtlab.fracture(v, f, pieces=4, seed=1, margin=0.02, recurse=[0], recurse_pieces=2)
    assert sum(p.volume for p in pieces) < pieces.mesh_volume
    assert sorted(p.parent for p in pieces).count(0) == 2


def test_open_mesh_is_refused():
    v, f = dtlab.read_mesh("builtin")
    with pytest.raises(ValueError):
        dtlab.fracture(v, f[1:], pieces=3)
