"""meshio in and out: Tetrahedralization.to_meshio, Pieces.to_meshio, from_meshio.
meshio is optional (Debian python3-meshio); without it these raise ImportError."""
from __future__ import annotations

from typing import Any

import numpy as np


def require_meshio() -> Any:
    try:
        import meshio
    except ImportError as e:
        raise ImportError("this needs meshio, which is not installed (Debian: apt install python3-meshio; "
                          "pip: pip install meshio)") from e
    return meshio


def tetrahedralization_mesh(points: np.ndarray, tets: np.ndarray) -> Any:
    """A meshio.Mesh of "tetra" cells in VTK's right-handed order (the first two of
    dtlab's orient3d > 0 vertices swapped, as the .vtu writer does)."""
    meshio = require_meshio()
    return meshio.Mesh(np.asarray(points, dtype=np.float64), [("tetra", np.asarray(tets)[:, [1, 0, 2, 3]])])


def pieces_mesh(pieces: Any) -> Any:
    """One meshio.Mesh of every piece's triangles, with cell data "piece" (its index)
    and "cut" (1 for a cut face)."""
    meshio = require_meshio()
    verts, faces, piece, cut = [], [], [], []
    base = 0
    for i, p in enumerate(pieces):
        verts.append(p.vertices)
        faces.append(np.asarray(p.faces, dtype=np.int64) + base)
        piece.append(np.full(len(p.faces), i, dtype=np.int64))
        cut.append(np.asarray(p.cut, dtype=np.uint8))
        base += len(p.vertices)
    if not verts:
        return meshio.Mesh(np.zeros((0, 3)), [("triangle", np.zeros((0, 3), dtype=np.int64))])
    return meshio.Mesh(np.concatenate(verts), [("triangle", np.concatenate(faces))],
                       cell_data={"piece": [np.concatenate(piece)], "cut": [np.concatenate(cut)]})


def mesh_arrays(mesh: Any) -> tuple[np.ndarray, np.ndarray]:
    """(vertices, triangles) of a meshio.Mesh: its "triangle" blocks, "quad" blocks split
    along a diagonal; any other surface cell type is refused with ValueError."""
    pts = np.asarray(mesh.points, dtype=np.float64)
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise ValueError(f"from_meshio: points must be 3D, got shape {pts.shape}")
    tris, other = [], []
    for block in mesh.cells:
        data = np.asarray(block.data, dtype=np.int64)
        if block.type == "triangle":
            tris.append(data)
        elif block.type == "quad":
            tris += [data[:, [0, 1, 2]], data[:, [0, 2, 3]]]
        elif block.type not in ("vertex", "line"):
            other.append(block.type)
    if not tris:
        found = ", ".join(sorted({b.type for b in mesh.cells})) or "none"
        raise ValueError(f"from_meshio: no triangle or quad cells (cell types: {found})")
    faces = np.concatenate(tris)
    if faces.size and (faces.min() < 0 or faces.max() >= len(pts)):
        raise ValueError("from_meshio: a face refers to a point out of range")
    if other:
        raise ValueError(f"from_meshio: cell types {', '.join(sorted(set(other)))} are not a triangle surface")
    return pts, faces.astype(np.uint32)
