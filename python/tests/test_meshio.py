"""meshio and VTK: to_meshio / from_meshio, and the Voronoi .vtu read by meshio and VTK."""
import subprocess
import sys

import numpy as np
import pytest

import dtlab
from conftest import write_xyz


def test_missing_meshio_is_a_clear_error():
    code = ("import sys; sys.modules['meshio'] = None\n"
            "import dtlab, numpy as np\n"
            "t = dtlab.tetrahedralize(np.random.default_rng(1).random((10, 3)))\n"
            "try:\n    t.to_meshio()\nexcept ImportError as e:\n    print(e)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert "needs meshio" in out and "python3-meshio" in out


meshio = pytest.importorskip("meshio", reason="meshio (python3-meshio) is not installed")


def test_tetrahedralization_to_meshio_round_trip(tmp_path):
    pts = dtlab.fuzz.generate("lattice", 300, seed=2)
    t = dtlab.tetrahedralize(pts)
    m = t.to_meshio()
    tets = m.cells_dict["tetra"]
    v = pts[tets]
    assert len(tets) == len(t.tets) and (np.linalg.det(v[:, 1:] - v[:, :1]) > 0).all()  # VTK's order
    meshio.write(tmp_path / "t.vtu", m)
    back = meshio.read(tmp_path / "t.vtu")
    assert dtlab.check(back.points, back.cells_dict["tetra"]).ok


def test_pieces_to_meshio_and_from_meshio():
    pieces = dtlab.fracture(*dtlab.read_mesh("builtin"), pieces=4)
    m = pieces.to_meshio()
    assert len(m.cells_dict["triangle"]) == sum(len(p.faces) for p in pieces)
    assert sorted(set(m.cell_data["piece"][0].tolist())) == [0, 1, 2, 3]
    assert m.cell_data["cut"][0].sum() == sum(int(p.cut.sum()) for p in pieces)
    torus = dtlab.read_mesh("builtin")
    mesh = dtlab.from_meshio(meshio.Mesh(torus.vertices, [("triangle", torus.faces)]))
    assert (mesh.vertices == torus.vertices).all() and (mesh.faces == torus.faces).all()
    assert len(dtlab.sample(mesh, 50)) == 50
    quad = meshio.Mesh(np.eye(4, 3), [("quad", np.array([[0, 1, 2, 3]]))])
    assert dtlab.from_meshio(quad).faces.shape == (2, 3)
    with pytest.raises(ValueError, match="no triangle or quad"):
        dtlab.from_meshio(meshio.Mesh(np.eye(4, 3), [("tetra", np.array([[0, 1, 2, 3]]))]))


@pytest.fixture(scope="module")
def voronoi_vtu(cli, tmp_path_factory):
    d = tmp_path_factory.mktemp("vor")
    pts = dtlab.sample("builtin", 300, seed=4)
    cli("voronoi", write_xyz(d / "p.xyz", pts), "--out", d / "cells", "--vtu", "--no-obj")
    return pts, str(d / "cells.vtu")


def test_voronoi_vtu_loads_in_meshio(voronoi_vtu):
    pts, path = voronoi_vtu
    m = meshio.read(path)  # failed before with "Incompatible cell data ... polyhedronN"
    cells = dtlab.voronoi(pts).cells
    blocks = [b for b in m.cells if b.type.startswith("polyhedron")]
    assert sum(len(b.data) for b in blocks) == len(pts) and len(blocks) > 3
    for block, site, volume in zip(blocks, m.cell_data["site"], m.cell_data["volume"]):
        k = int(block.type[len("polyhedron"):])
        assert all(len(cells[s].vertices) == k for s in site)  # cell data matches its cells
        assert np.allclose(volume, [cells[s].volume for s in site], rtol=1e-12)


def test_voronoi_vtu_loads_in_vtk(voronoi_vtu):
    vtk = pytest.importorskip("vtk", reason="VTK (python3-vtk9) is not installed")
    pts, path = voronoi_vtu
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfCells() == len(pts)
    assert all(grid.GetCellType(i) == vtk.VTK_POLYHEDRON for i in range(grid.GetNumberOfCells()))
    site = grid.GetCellData().GetArray("site")
    cells = dtlab.voronoi(pts).cells
    for i in range(0, grid.GetNumberOfCells(), 17):
        assert grid.GetCell(i).GetNumberOfPoints() == len(cells[int(site.GetValue(i))].vertices)
