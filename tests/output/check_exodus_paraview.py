# SPDX-License-Identifier: MIT
"""ParaView 5.11 opens results.exo (CTest output_exodus_paraview, run by pvbatch with DISPLAY unset:
reading needs no X server). Usage: pvbatch check_exodus_paraview.py RESULTS.exo NODES ELEMENTS STEPS

IOSSReader (ParaView 5.11's reader for .exo/.e/.g) must give the point and cell counts, the time
steps, the element block names (bar, cap) and the component variables recombined: displacement,
velocity, force, acceleration as 3-component vectors, stress as a 6-component symmetric tensor
whose components have the ranges of stress_xx, _yy, _zz, _xy, _yz, _zx in the file (read with
netCDF4), equivalent_plastic_strain as a scalar, and the history columns as global (field) data
(momentum recombined too). The legacy ExodusIIReader must open it with the same counts and steps
(it recombines vectors as `displacement_` and leaves the tensor as six scalars).
"""
import os
import sys

import netCDF4
import numpy as np
from paraview.simple import ExodusIIReader, IOSSReader


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def arrays(data):
    return {k: data[k].GetNumberOfComponents() for k in data.keys()}


def main():
    path, nodes, elements, steps = os.path.abspath(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
    r = IOSSReader(FileName=[path])
    r.UpdatePipelineInformation()
    if len(r.TimestepValues) != steps:
        fail(f"IOSSReader: {len(r.TimestepValues)} time steps, expected {steps}")
    r.UpdatePipeline(r.TimestepValues[-1])
    info = r.GetDataInformation()
    # Blocks do not share nodes in the test mesh, so the per-block points add up to the nodes.
    if info.GetNumberOfPoints() != nodes or info.GetNumberOfCells() != elements:
        fail(f"IOSSReader: {info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells; expected {nodes}, {elements}")
    blocks = sorted(r.ElementBlocks.Available)
    if blocks != ["bar", "cap"]:
        fail(f"IOSSReader: element blocks {blocks}, expected ['bar', 'cap']")
    point, cell, field = arrays(r.PointData), arrays(r.CellData), arrays(r.FieldData)
    for name, components in {"displacement": 3, "velocity": 3, "force": 3, "acceleration": 3}.items():
        if point.get(name) != components:
            fail(f"IOSSReader: point array {name} with {components} components missing; point arrays: {point}")
    for name, components in {"stress": 6, "equivalent_plastic_strain": 1}.items():
        if cell.get(name) != components:
            fail(f"IOSSReader: cell array {name} with {components} components missing; cell arrays: {cell}")
    if "kinetic_energy" not in field or field.get("momentum") != 3:
        fail(f"IOSSReader: global variables kinetic_energy and momentum (3) missing; field arrays: {field}")

    # Component order of the tensor: ParaView's component k has the range of the file's variable k.
    exo = netCDF4.Dataset(path)
    var_names = ["".join(c.decode() for c in row if c not in (b"", b"\x00")) for row in exo.variables["name_elem_var"][:].data]
    nblocks = exo.dimensions["num_el_blk"].size
    for k, suffix in enumerate(("xx", "yy", "zz", "xy", "yz", "zx")):
        v = var_names.index("stress_" + suffix) + 1
        values = np.concatenate([exo.variables[f"vals_elem_var{v}eb{b + 1}"][-1, :].data for b in range(nblocks)])
        got = r.CellData["stress"].GetRange(k)
        if not np.allclose(got, (values.min(), values.max()), rtol=1e-12, atol=0.0):
            fail(f"IOSSReader: stress component {k} has range {got}, stress_{suffix} in the file {values.min(), values.max()}")
    lo, hi = r.PointData["displacement"].GetRange(2)
    if not lo < 0.0:
        fail(f"IOSSReader: displacement z range ({lo}, {hi}) at the last step: the piston moved nothing")

    e = ExodusIIReader(FileName=[path])
    e.PointVariables = list(e.PointVariables.Available)
    e.ElementVariables = list(e.ElementVariables.Available)
    e.UpdatePipeline(e.TimestepValues[-1])
    legacy = e.GetDataInformation()
    if len(e.TimestepValues) != steps or legacy.GetNumberOfPoints() != nodes or legacy.GetNumberOfCells() != elements:
        fail(f"ExodusIIReader: {len(e.TimestepValues)} steps, {legacy.GetNumberOfPoints()} points, "
             f"{legacy.GetNumberOfCells()} cells")
    if arrays(e.PointData).get("displacement_") != 3 or "stress_zx" not in arrays(e.CellData):
        fail(f"ExodusIIReader: arrays {arrays(e.PointData)} {arrays(e.CellData)}")
    print(f"IOSSReader: {nodes} points, {elements} cells, {steps} steps, blocks {blocks}; point arrays {point}; "
          f"cell arrays {cell}; {len(field)} field arrays; stress components in the file's order")
    print("ExodusIIReader: same counts and steps; vectors as displacement_ ..., stress as six scalars")
    print("PASS")


if __name__ == "__main__":
    main()
