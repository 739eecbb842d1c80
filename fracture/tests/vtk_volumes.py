#!/usr/bin/env python3
"""VTK integrates dtlab's fracture pieces to the manifest's volumes.

    /usr/bin/python3 fracture/tests/vtk_volumes.py OUT_DIR [--tolerance 1e-9]

OUT_DIR is a `dtlab fracture ... --surfaces --vtu` output. Each piece of surfaces.vtu
(its triangles, selected by the `piece` cell array with vtkThreshold) goes through
vtkGeometryFilter and vtkMassProperties; its volume must match the manifest's within
the relative tolerance. pieces.vtu's polyhedron cells are measured with vtkCellSizeFilter
for comparison (printed only: VTK 9.1 mis-integrates non-convex polyhedra). Exit 0 ok,
1 on a mismatch, 77 (skip) without VTK.
"""
import json
import os
import sys

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("SKIP: python3-vtk9 is not installed")
    sys.exit(77)


def read(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def piece_volume(grid, i):
    th = vtk.vtkThreshold()
    th.SetInputData(grid)
    th.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_CELLS, "piece")
    th.SetLowerThreshold(i - 0.5)
    th.SetUpperThreshold(i + 0.5)
    th.SetThresholdFunction(vtk.vtkThreshold.THRESHOLD_BETWEEN)
    geo = vtk.vtkGeometryFilter()
    geo.SetInputConnection(th.GetOutputPort())
    mp = vtk.vtkMassProperties()
    mp.SetInputConnection(geo.GetOutputPort())
    mp.Update()
    return mp.GetVolume()


def main():
    out = sys.argv[1]
    tol = float(sys.argv[sys.argv.index("--tolerance") + 1]) if "--tolerance" in sys.argv else 1e-9
    manifest = json.load(open(os.path.join(out, "manifest.json")))
    grid = read(os.path.join(out, "surfaces.vtu"))
    worst, fails = 0.0, 0
    for i, p in enumerate(manifest["pieces"]):
        v = piece_volume(grid, i)
        err = abs(v - p["volume"]) / abs(p["volume"])
        worst = max(worst, err)
        if err > tol:
            fails += 1
            print(f"FAIL: piece {i}: VTK {v!r}, manifest {p['volume']!r} (relative {err:.2e})")
    print(f"vtkMassProperties on surfaces.vtu: {len(manifest['pieces'])} pieces, worst relative error {worst:.2e}")
    if os.path.exists(os.path.join(out, "pieces.vtu")):
        cs = vtk.vtkCellSizeFilter()
        cs.SetInputData(read(os.path.join(out, "pieces.vtu")))
        cs.Update()
        vols = vtk_to_numpy(cs.GetOutput().GetCellData().GetArray("Volume"))
        print(f"vtkCellSizeFilter on pieces.vtu (polyhedra): sum {vols.sum():.6g} vs mesh {manifest['mesh_volume']:.6g}")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
