#!/usr/bin/env python3
"""VTK and meshio read dtlab's tetrahedralized pieces (tets.vtu) to the manifest's volumes.

    /usr/bin/python3 fracture/tests/tet_volumes.py OUT_DIR [--tolerance 1e-9]

OUT_DIR is a `dtlab fracture ... --tets` output. VTK: vtkCellSizeFilter gives every
VTK_TETRA cell's volume (it must be positive: VTK's orientation); summed per `piece`
cell value they must match the manifest's piece volumes within the relative tolerance.
meshio: reads the file, one block of "tetra" cells with the `piece` cell data, the same
sums from its own determinant. Exit 0 ok, 1 on a mismatch, 77 (skip) when neither VTK
nor meshio is installed (each missing one is reported and skipped).
"""
import json
import os
import sys


def check(name, vols, piece, manifest, tol):
    bad = 0
    sums = {}
    for v, p in zip(vols, piece):
        if not v > 0:
            bad += 1
        sums[int(p)] = sums.get(int(p), 0.0) + float(v)
    worst = 0.0
    for p in manifest["pieces"]:
        want = p["volume"]
        got = sums.get(p["id"], 0.0)
        worst = max(worst, abs(got - want) / abs(want))
    ok = bad == 0 and worst <= tol and len(sums) == len(manifest["pieces"])
    print("%s: %d tets, %d not positive, %d pieces, largest relative volume difference %.2e" %
          (name, len(vols), bad, len(sums), worst))
    return ok


def main():
    out = sys.argv[1]
    tol = float(sys.argv[sys.argv.index("--tolerance") + 1]) if "--tolerance" in sys.argv else 1e-9
    manifest = json.load(open(os.path.join(out, "manifest.json")))
    path = os.path.join(out, "tets.vtu")
    ran, ok = 0, True
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        r = vtk.vtkXMLUnstructuredGridReader()
        r.SetFileName(path)
        r.Update()
        cs = vtk.vtkCellSizeFilter()
        cs.SetInputConnection(r.GetOutputPort())
        cs.ComputeVolumeOn()
        cs.Update()
        g = cs.GetOutput()
        vols = vtk_to_numpy(g.GetCellData().GetArray("Volume"))
        piece = vtk_to_numpy(g.GetCellData().GetArray("piece"))
        ok = check("VTK", vols, piece, manifest, tol) and ok
        ran += 1
    except ImportError:
        print("SKIP VTK: python3-vtk9 is not installed")
    try:
        import meshio
        import numpy as np
        m = meshio.read(path)
        blocks = [b for b in m.cells if b.type == "tetra"]
        assert len(blocks) == 1 and len(m.cells) == 1, [b.type for b in m.cells]
        t = blocks[0].data
        p = m.points
        a, b, c, d = p[t[:, 0]], p[t[:, 1]], p[t[:, 2]], p[t[:, 3]]
        vols = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6
        ok = check("meshio", vols, m.cell_data["piece"][0], manifest, tol) and ok
        ran += 1
    except ImportError:
        print("SKIP meshio: python3-meshio is not installed")
    if ran == 0:
        sys.exit(77)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
