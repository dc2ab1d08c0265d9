# SPDX-License-Identifier: MIT
"""ParaView draws the results.exo of a nanometre model without a Transform and finds the new fields
by name (issue 56 acceptance; CTest output_render_exodus, pvbatch under xvfb-run).

usage: pvbatch render_exodus.py RESULTS.exo OUT.png
Checks (exit 1, one line): the first info record is `tribex length unit: nm`; IOSSReader gives the
cell array `von_mises` and the point array `contact_pressure` (one component each) and a model
extent in nm (between 1 and 1000: not the 1e-8 of metres); then draws von_mises on the section
y = y_c through the contact centre (seen from -y, x to the right), deformed by the displacement, at
the step with the most nodes in contact, framed on the contact, for check_render_png.py. Prints
one line with the figures.
"""
import builtins
import os
import sys

import netCDF4
import numpy as np
from paraview.simple import (CellDatatoPointData, Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             IOSSReader, MergeBlocks, Render, SaveScreenshot, Show, WarpByVector)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def text(exo, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in exo.variables[var][:].data]


def contact_frame(path):
    """(step, centre, radius) of the step with the most nodes in contact, in the file's unit."""
    with netCDF4.Dataset(path) as exo:
        info, nodal = text(exo, "info_records"), text(exo, "name_nod_var")
        if not info or info[0] != "tribex length unit: nm":
            fail(f"{path}: first info record {info[:1]}, expected 'tribex length unit: nm'")
        var = {n: f"vals_nod_var{i + 1}" for i, n in enumerate(nodal)}
        status = exo.variables[var["contact_status"]][:].data
        k = int(np.argmax((status > 0).sum(axis=1)))
        x = np.stack([exo.variables[c][:].data + exo.variables[var[f"displacement_{c[-1]}"]][k, :].data
                      for c in ("coordx", "coordy", "coordz")], axis=1)
    on = x[status[k] > 0]
    centre = on.mean(axis=0)
    return k, centre, float(np.max(np.hypot(on[:, 0] - centre[0], on[:, 1] - centre[1])))


def main():
    path, png = os.path.abspath(sys.argv[1]), sys.argv[2]
    k, centre, radius = contact_frame(path)
    reader = IOSSReader(FileName=[path])
    reader.UpdatePipelineInformation()
    t = reader.TimestepValues[k]
    source = MergeBlocks(Input=reader)
    source.UpdatePipeline(t)
    point = {n: source.PointData[n].GetNumberOfComponents() for n in source.PointData.keys()}
    cell = {n: source.CellData[n].GetNumberOfComponents() for n in source.CellData.keys()}
    if cell.get("von_mises") != 1 or point.get("contact_pressure") != 1:
        fail(f"IOSSReader: von_mises (cell) or contact_pressure (point) missing: point {point}, cell {cell}")
    b = source.GetDataInformation().GetBounds()
    extent = builtins.max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
    if not 1.0 < extent < 1000.0:
        fail(f"model extent {extent:g}: not in nm")
    p_lo, p_hi = source.PointData["contact_pressure"].GetRange()
    warp = WarpByVector(Input=source)
    warp.Vectors = ["POINTS", "displacement"]
    smooth = CellDatatoPointData(Input=warp)
    smooth.PassCellData = 0
    clip = Clip(Input=smooth)  # y >= y_c, seen from -y: x to the right, z up
    clip.ClipType = "Plane"
    clip.ClipType.Origin = list(centre)
    clip.ClipType.Normal = [0.0, 1.0, 0.0]
    clip.Invert = 0
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1024, 768]
    view.ViewTime = t
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 0
    display = Show(clip, view)
    ColorBy(display, ("POINTS", "von_mises"))
    GetColorTransferFunction("von_mises").ApplyPreset("Viridis (matplotlib)", True)
    display.RescaleTransferFunctionToDataRange(False, True)
    Render(view)
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = list(centre)
    view.CameraPosition = [centre[0], centre[1] - 4.0 * extent, centre[2]]
    view.CameraViewUp = [0, 0, 1]
    view.CameraParallelScale = builtins.max(3.0 * radius, 0.08 * extent)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[1024, 768], TransparentBackground=0)
    print(f"{png}: results.exo in nm (extent {extent:.4g} nm), von_mises on the section at step {k}, "
          f"contact radius {radius:.3g} nm; contact_pressure {p_lo:.4g} .. {p_hi:.4g} Pa")


if __name__ == "__main__":
    main()
