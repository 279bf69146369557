#!/usr/bin/python3
"""Checks .vtu files written by CGAL::IO::write_tet_mesh_VTU with VTK's own reader.

Usage: /usr/bin/python3 check_vtu.py expected.json file1.vtu [file2.vtu ...]

expected.json (written by test_tet_mesh_io) holds number_of_points, number_of_cells,
points, tets and fields {name: values}. Reading with VTK rather than a hand-written
parser is the point: it proves ParaView-class readers accept the files.
Exits non-zero, listing every failed check, if anything differs.
"""
import json
import sys

import vtk
from vtk.util.numpy_support import vtk_to_numpy
import numpy as np

VTK_TETRA = 10


def check(path, expected):
    errors = []

    def fail(msg):
        errors.append(f"{path}: {msg}")

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode() != 0:
        fail(f"reader error code {reader.GetErrorCode()}")
    grid = reader.GetOutput()
    if grid is None:
        fail("no output")
        return errors

    n, nc = grid.GetNumberOfPoints(), grid.GetNumberOfCells()
    if n != expected["number_of_points"]:
        fail(f"{n} points, expected {expected['number_of_points']}")
    if nc != expected["number_of_cells"]:
        fail(f"{nc} cells, expected {expected['number_of_cells']}")
    if errors:
        return errors

    pts = vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
    exp_pts = np.asarray(expected["points"], dtype=np.float64)
    if pts.shape != exp_pts.shape or not np.array_equal(pts, exp_pts):
        fail("point coordinates differ from the expected ones")

    tets = []
    for c in range(nc):
        if grid.GetCellType(c) != VTK_TETRA:
            fail(f"cell {c} has type {grid.GetCellType(c)}, expected VTK_TETRA")
            continue
        ids = grid.GetCell(c).GetPointIds()
        tets.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    if tets != expected["tets"]:
        fail("tetrahedra differ from the expected ones")

    # positive orientation: det(b-a, c-a, d-a) > 0, the convention of VTK and CGAL
    for c, t in enumerate(tets):
        if len(t) != 4:
            continue
        a, b, cc, d = (np.asarray(grid.GetPoint(i)) for i in t)
        vol = np.linalg.det(np.array([b - a, cc - a, d - a])) / 6.0
        if not vol > 0.0:
            fail(f"cell {c} {t} has signed volume {vol}")

    pd = grid.GetPointData()
    for name, values in expected["fields"].items():
        arr = pd.GetArray(name)
        if arr is None:
            fail(f"point array '{name}' is missing")
            continue
        if arr.GetDataType() != vtk.VTK_DOUBLE:
            fail(f"point array '{name}' is not Float64")
        got = vtk_to_numpy(arr).astype(np.float64)
        if got.shape != (n,) or not np.array_equal(got, np.asarray(values, dtype=np.float64)):
            fail(f"point array '{name}' = {got.tolist()}, expected {values}")
    if pd.GetNumberOfArrays() != len(expected["fields"]):
        fail(f"{pd.GetNumberOfArrays()} point arrays, expected {len(expected['fields'])}")
    return errors


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        expected = json.load(f)
    errors = []
    for path in argv[2:]:
        errors += check(path, expected)
    for e in errors:
        print("FAILED", e, file=sys.stderr)
    if not errors:
        print(f"check_vtu: {len(argv) - 2} file(s) OK")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
