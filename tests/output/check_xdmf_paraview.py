# SPDX-License-Identifier: MIT
"""Acceptance test: ParaView opens the sample results.xdmf written by tribex_write_sample_results.

Run with pvpython: pvpython check_xdmf_paraview.py /ABSOLUTE/path/results.xdmf [m|nm]
Both of ParaView 5.11's XDMF readers are checked: XDMFReader (Xdmf2) in full; Xdmf3ReaderS for what
it reads of the per-block grids (hexes and nodal fields; it skips HyperSlab cell attributes). The expected
values repeat the formulas of tests/output/sample_case.hpp: a 3 x 2 x 2 box of unit hexes (unit:
1 m, or 1 nm for the nm sample, whose file is then in nm), times 0, 0.25, 0.5; displacement
u = t (x, 2y, -z) (in the file's length unit, like x); stress (Voigt) = (e+1)(1+t)(1..6) stored as a
full 3x3 tensor; slip = (t e, -t) m as a 2-component Matrix (x 1e9 in the nm file); temperature
300 + t x (x in m). The output is one block per element block, named substrate (elements 0-5) and
asperity (6-11), each with its 6 hexes and the whole node array (36 points); array names are the bare
field names ("displacement", not "displacement [nm]": the unit is the attribute's <Information
Name="units">), block_id stays.
Prints one line per check and exits 1 on the first failure.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import XDMFReader, Xdmf3ReaderS
from vtk.numpy_interface import dataset_adapter as dsa
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet

TIMES = [0.0, 0.25, 0.5]
NODES, ELEMENTS = 36, 12
BLOCKS = [("substrate", 0, 6), ("asperity", 6, 6)]  # name, first element, elements
VOIGT_OF_FULL = [0, 3, 5, 3, 1, 4, 5, 4, 2]  # full row-major entry k -> Voigt component


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(b))


def named_blocks(reader, t):
    """The leaf datasets of the reader's output at time t as [(name, dataset)] in order."""
    reader.UpdatePipeline(t)
    leaves = []

    def walk(obj, name):
        if obj is None:
            return
        if obj.IsA("vtkMultiBlockDataSet"):
            for i in range(obj.GetNumberOfBlocks()):
                meta = obj.GetMetaData(i) if obj.HasMetaData(i) else None
                child = meta.Get(vtkCompositeDataSet.NAME()) if meta and meta.Has(vtkCompositeDataSet.NAME()) else None
                walk(obj.GetBlock(i), child)
        else:
            leaves.append((name, dsa.WrapDataObject(obj)))

    walk(servermanager.Fetch(reader), None)
    return leaves


def check(reader_name, reader, unit):
    per_m = 1e9 if unit == "nm" else 1.0
    times = list(reader.TimestepValues)
    if len(times) != len(TIMES) or not all(close(a, b) for a, b in zip(times, TIMES)):
        fail(f"{reader_name}: time steps {times}, expected {TIMES}")
    t = TIMES[2]
    leaves = named_blocks(reader, t)
    names = [n for n, _ in leaves]
    if names != [b[0] for b in BLOCKS]:
        fail(f"{reader_name}: blocks {names}, expected {[b[0] for b in BLOCKS]}")
    for (name, first, count), (_, data) in zip(BLOCKS, leaves):
        if data.GetNumberOfPoints() != NODES or data.GetNumberOfCells() != count:
            fail(f"{reader_name}: block {name}: {data.GetNumberOfPoints()} points / {data.GetNumberOfCells()} cells, "
                 f"expected {NODES} / {count}")
        if any(data.GetCellType(c) != 12 for c in range(count)):  # 12 = VTK_HEXAHEDRON
            fail(f"{reader_name}: block {name}: not every cell is a hexahedron")
        expected_arrays = {"displacement", "temperature"}
        if not expected_arrays <= set(data.PointData.keys()):
            fail(f"{reader_name}: block {name}: point arrays {data.PointData.keys()}, expected {expected_arrays}")
        points = data.Points
        u = data.PointData["displacement"]
        for n in (0, 7, NODES - 1):
            x, y, z = points[n]
            expected = (t * x, 2 * t * y, -t * z)
            got = [float(v) for v in u[n]]
            if not all(close(g, e) for g, e in zip(got, expected)):
                fail(f"{reader_name}: block {name}: displacement at node {n} = {got}, expected {expected} (t={t})")
        stress = data.CellData["stress"].reshape(count, 9)  # readers return 3x3 per cell
        slip = data.CellData["slip"]
        block = [int(b) for b in data.CellData["block_id"]]
        if block != [BLOCKS.index((name, first, count))] * count:
            fail(f"{reader_name}: block {name}: block_id {block}")
        for c in range(count):
            e = first + c
            expected = [(e + 1) * (1 + t) * (VOIGT_OF_FULL[k] + 1) for k in range(9)]
            got = [float(v) for v in stress[c]]
            if not all(close(g, x) for g, x in zip(got, expected)):
                fail(f"{reader_name}: stress of cell {e} = {got}, expected {expected}")
            got = [float(v) for v in slip[c]]  # 2 components: XDMF "Matrix"
            if not (close(got[0], t * e * per_m) and close(got[1], -t * per_m)):
                fail(f"{reader_name}: slip of cell {e} = {got}, expected {[t * e * per_m, -t * per_m]}")
    # The mesh comes from step 0 by xi:include: an earlier step must read too, with its own values.
    early = named_blocks(reader, TIMES[1])
    x1 = float(early[1][1].Points[1][0]) / per_m  # node 1, in m
    if [d.GetNumberOfCells() for _, d in early] != [b[2] for b in BLOCKS] or not close(
            float(early[1][1].PointData["temperature"][1]), 300 + 0.25 * x1):
        fail(f"{reader_name}: step 1 temperature at node 1 wrong or mesh missing")
    print(f"ok: {reader_name}: blocks {names} ({'/'.join(str(b[2]) for b in BLOCKS)} hexes, {NODES} points each), "
          f"{len(TIMES)} steps, lengths in {unit}, displacement/stress/slip/block_id at t={t} match")


def check_xdmf3(reader_name, reader, unit):
    """Xdmf3ReaderS reads the blocks' hexes and nodal fields as pieces of one dataset, without names,
    and skips cell attributes given as HyperSlabs (solver/output/README.md, "XDMF layout")."""
    times = list(reader.TimestepValues)
    if len(times) != len(TIMES) or not all(close(a, b) for a, b in zip(times, TIMES)):
        fail(f"{reader_name}: time steps {times}, expected {TIMES}")
    t = TIMES[2]
    reader.UpdatePipeline(t)
    pieces = []

    def walk(obj):
        if obj is None:
            return
        if obj.IsA("vtkDataSet"):
            pieces.append(dsa.WrapDataObject(obj))
        else:
            it = obj.NewIterator()
            it.InitTraversal()
            while not it.IsDoneWithTraversal():
                pieces.append(dsa.WrapDataObject(it.GetCurrentDataObject()))
                it.GoToNextItem()

    walk(servermanager.Fetch(reader))
    cells = sorted(p.GetNumberOfCells() for p in pieces)
    if cells != sorted(b[2] for b in BLOCKS):
        fail(f"{reader_name}: pieces with {cells} cells, expected {[b[2] for b in BLOCKS]}")
    for data in pieces:
        u = data.PointData["displacement"]
        x, y, z = data.Points[7]
        got = [float(v) for v in u[7]]
        if not all(close(g, e) for g, e in zip(got, (t * x, 2 * t * y, -t * z))):
            fail(f"{reader_name}: displacement at node 7 = {got}")
    print(f"ok: {reader_name}: {len(pieces)} unnamed pieces of {'/'.join(map(str, cells))} hexes, displacement "
          f"({unit}) matches (cell fields: XDMF Reader only)")


def main():
    if len(sys.argv) not in (2, 3) or not os.path.isabs(sys.argv[1]):
        fail("usage: pvpython check_xdmf_paraview.py /ABSOLUTE/path/results.xdmf [m|nm] "
             "(Xdmf3 resolves the .h5 wrongly from a bare relative name)")
    path = sys.argv[1]
    unit = sys.argv[2] if len(sys.argv) == 3 else "m"
    if not os.path.isfile(path):
        fail(f"{path}: no such file; run tribex_write_sample_results first")
    check("XDMFReader", XDMFReader(FileNames=[path]), unit)
    check_xdmf3("Xdmf3ReaderS", Xdmf3ReaderS(FileName=[path]), unit)


if __name__ == "__main__":
    main()
