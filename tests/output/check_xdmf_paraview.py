# SPDX-License-Identifier: MIT
"""Acceptance test: ParaView opens the sample results.xdmf written by tribex_write_sample_results.

Run with pvpython: pvpython check_xdmf_paraview.py /ABSOLUTE/path/results.xdmf
Both of ParaView 5.11's XDMF readers are checked (XDMFReader = Xdmf2, Xdmf3ReaderS). The expected
values repeat the formulas of tests/output/sample_case.hpp: a 3 x 2 x 2 box of unit hexes, times
0, 0.25, 0.5; displacement u = t (x, 2y, -z); stress (Voigt) = (e+1)(1+t)(1..6) stored as a full
3x3 tensor; slip = (t e, -t) as a 2-component Matrix; block_id 0 for the 6 lower elements,
1 for the 6 upper ones.
Prints one line per check and exits 1 on the first failure.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import XDMFReader, Xdmf3ReaderS
from vtk.numpy_interface import dataset_adapter as dsa

TIMES = [0.0, 0.25, 0.5]
NODES, ELEMENTS = 36, 12
VOIGT_OF_FULL = [0, 3, 5, 3, 1, 4, 5, 4, 2]  # full row-major entry k -> Voigt component


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(b))


def check(reader_name, reader):
    times = list(reader.TimestepValues)
    if len(times) != len(TIMES) or not all(close(a, b) for a, b in zip(times, TIMES)):
        fail(f"{reader_name}: time steps {times}, expected {TIMES}")
    step, t = 2, TIMES[2]
    reader.UpdatePipeline(t)
    data = dsa.WrapDataObject(servermanager.Fetch(reader))
    if data.GetNumberOfPoints() != NODES or data.GetNumberOfCells() != ELEMENTS:
        fail(f"{reader_name}: {data.GetNumberOfPoints()} nodes / {data.GetNumberOfCells()} cells, "
             f"expected {NODES} / {ELEMENTS}")
    if any(data.GetCellType(c) != 12 for c in range(ELEMENTS)):  # 12 = VTK_HEXAHEDRON
        fail(f"{reader_name}: not every cell is a hexahedron")
    points = data.Points
    u = data.PointData["displacement"]
    for n in (0, 7, NODES - 1):
        x, y, z = points[n]
        expected = (t * x, 2 * t * y, -t * z)
        got = [float(v) for v in u[n]]
        if not all(close(g, e) for g, e in zip(got, expected)):
            fail(f"{reader_name}: displacement at node {n} = {got}, expected {expected} (t={t})")
    stress = data.CellData["stress"].reshape(ELEMENTS, 9)  # readers return 3x3 per cell
    e = 4
    expected = [(e + 1) * (1 + t) * (VOIGT_OF_FULL[k] + 1) for k in range(9)]
    got = [float(v) for v in stress[e]]
    if not all(close(g, x) for g, x in zip(got, expected)):
        fail(f"{reader_name}: stress of cell {e} = {got}, expected {expected}")
    slip = [float(v) for v in data.CellData["slip"][e]]  # 2 components: XDMF "Matrix"
    if not (close(slip[0], t * e) and close(slip[1], -t)):
        fail(f"{reader_name}: slip of cell {e} = {slip}, expected {[t * e, -t]}")
    block = [int(b) for b in data.CellData["block_id"]]
    if block != [0] * 6 + [1] * 6:
        fail(f"{reader_name}: block_id {block}")
    # The mesh comes from step 0 by xi:include: an earlier step must read too, with its own values.
    reader.UpdatePipeline(TIMES[1])
    early = dsa.WrapDataObject(servermanager.Fetch(reader))
    if early.GetNumberOfCells() != ELEMENTS or not close(float(early.PointData["temperature"][1]), 300.25):
        fail(f"{reader_name}: step 1 temperature at node 1 wrong or mesh missing")
    print(f"ok: {reader_name}: {NODES} nodes, {ELEMENTS} hexes, {len(TIMES)} steps, "
          f"displacement/stress/slip/block_id at t={t} match")


def main():
    if len(sys.argv) != 2 or not os.path.isabs(sys.argv[1]):
        fail("usage: pvpython check_xdmf_paraview.py /ABSOLUTE/path/results.xdmf "
             "(Xdmf3 resolves the .h5 wrongly from a bare relative name)")
    path = sys.argv[1]
    if not os.path.isfile(path):
        fail(f"{path}: no such file; run tribex_write_sample_results first")
    check("XDMFReader", XDMFReader(FileNames=[path]))
    check("Xdmf3ReaderS", Xdmf3ReaderS(FileName=[path]))


if __name__ == "__main__":
    main()
