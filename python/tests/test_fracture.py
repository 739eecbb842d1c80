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
    # The volume identity in floating point and computed exactly on the returned doubles.
    vi = pieces.manifest["volume_identity"]
    assert abs(vi["float_relative"]) < 1e-12 and abs(vi["exact_relative"]) < 1e-14
    assert vi["exact"] == (vi["exact_difference"] == 0)


def test_margin_loses_volume_and_recursion():
    v, f = dtlab.read_mesh("builtin")
    pieces = dtlab.fracture(v, f, pieces=4, seed=1, margin=0.02, recurse=[0], recurse_pieces=2)
    assert sum(p.volume for p in pieces) < pieces.mesh_volume
    assert sorted(p.parent for p in pieces).count(0) == 2


def test_open_mesh_is_refused():
    v, f = dtlab.read_mesh("builtin")
    with pytest.raises(ValueError):
        dtlab.fracture(v, f[1:], pieces=3)


def components(faces):
    parent = list(range(len(faces)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    first = {}
    for i, t in enumerate(faces):
        for k in range(3):
            e = tuple(sorted((int(t[k]), int(t[(k + 1) % 3]))))
            if e in first:
                parent[find(i)] = find(first[e])
            else:
                first[e] = i
    return len({find(i) for i in range(len(faces))})


def test_islands_and_site_sources():
    v, f = dtlab.read_mesh("builtin")
    split = dtlab.fracture(v, f, pieces=6, seed=1, threads=2)
    whole = dtlab.fracture(v, f, pieces=6, seed=1, threads=2, island_split=False)
    assert len(split) == 7 and len(whole) == 6
    assert all(components(p.faces) == 1 for p in split)
    assert sum(components(p.faces) > 1 for p in whole) == 1
    assert sorted(p.island for p in split).count(1) == 1
    given = dtlab.fracture(v, f, sites=np.array([[1.0, 0, 0], [-1, 0, 0], [0, 1, 0]]), threads=2)
    assert {p.site_index for p in given} == {0, 1, 2} and given[0].site == (1.0, 0.0, 0.0)
    mv = dtlab.fracture(v, f, pieces=5, sites="mesh-vertices", threads=2, density=2.0)
    verts = {tuple(x) for x in v}
    assert all(p.site in verts for p in mv)
    assert mv.manifest["pieces"][0]["mass"] == 2.0 * mv[0].volume
    imp = dtlab.fracture(v, f, pieces=8, impact=(1, 0, 0), impact_radius=0.2, site_noise=0.01, threads=2,
                         cell_scale=(1, 1, 2))
    assert imp.relative_volume_error < 1e-12
    assert np.mean([np.linalg.norm(np.subtract(p.site, (1, 0, 0))) for p in imp]) < 0.5
    with pytest.raises(ValueError):
        dtlab.fracture(v, f, sites="vertices")
    with pytest.raises(ValueError):
        dtlab.fracture(v, f, impact=(1, 0, 0))
    with pytest.raises(ValueError):
        dtlab.fracture(v, f, cell_scale=(1, 2))
