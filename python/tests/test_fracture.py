import shutil
from fractions import Fraction

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


def det3(a, b, c):
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])


def exact(rows):
    return [[Fraction(float(x)) for x in r] for r in rows]


def tets_volume6(points, tets):
    """6 x the tets' volume in exact rational arithmetic (Fractions of the doubles)."""
    total = Fraction(0)
    for t in tets:
        a, b, c, d = exact(points[list(t)])
        total += det3(*([p[k] - a[k] for k in range(3)] for p in (b, c, d)))
    return total


def surface_volume6(vertices, faces):
    """6 x the volume a closed surface bounds, exactly (sum of a . (b x c))."""
    return sum((det3(*exact(vertices[list(t)])) for t in faces), Fraction(0))


def test_exact_tiling_and_tets_as_the_cli():
    v, f = dtlab.read_mesh("builtin")
    proved = dtlab.fracture(v, f, pieces=5, seed=2, threads=2, exact_tiling=True)
    tiling = proved.manifest["volume_identity"]["exact_tiling"]
    assert tiling["holds"] is True and tiling["difference"] == 0
    plain = dtlab.fracture(v, f, pieces=5, seed=2, threads=2)
    assert "exact_tiling" not in plain.manifest["volume_identity"]
    assert all(p.tets is None and p.tet_points is None for p in plain)
    # With a gap no tiling is claimed (the CLI's --exact-tiling with --gap).
    gap = dtlab.fracture(v, f, pieces=5, seed=2, margin=0.02, exact_tiling=True)
    assert "exact_tiling" not in gap.manifest["volume_identity"]
    if shutil.which("tetgen") is None:
        pytest.skip("tetgen is not installed")
    meshed = dtlab.fracture(v, f, pieces=3, seed=2, threads=2, tets=True)
    assert meshed.manifest["tets"]["pieces_exact"] == meshed.manifest["tets"]["pieces"] == len(meshed)
    for i, p in enumerate(meshed):
        assert p.tets.shape[1] == 4 and p.tets.dtype == np.uint32 and len(p.tets) > 0
        assert np.array_equal(p.tet_points[:len(p.vertices)], p.vertices)  # the surface bit for bit
        assert meshed.manifest["pieces"][i]["tets"] == len(p.tets)
        # Tets in dtlab's orientation (orient3d > 0: det(b - a, c - a, d - a) < 0) whose
        # volumes add up to the piece's (checked here, not trusted).
        o = p.tet_points[p.tets[:, 0]]
        det = np.einsum("ij,ij->i", p.tet_points[p.tets[:, 1]] - o,
                        np.cross(p.tet_points[p.tets[:, 2]] - o, p.tet_points[p.tets[:, 3]] - o))
        assert (det < 0).all()
        assert abs(-det.sum() / 6 - p.volume) <= 1e-12 * p.volume
    first = meshed[0]  # the exact check on one piece (Fractions are slow)
    assert -tets_volume6(first.tet_points, first.tets) == surface_volume6(first.vertices, first.faces)
    with pytest.raises(RuntimeError, match="tetgen"):
        dtlab.fracture(v, f, pieces=2, seed=2, tets=True, tetgen="/nonexistent/tetgen")
