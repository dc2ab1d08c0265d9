# SPDX-License-Identifier: MIT
"""Render a PNG of a tribex results.xdmf coloured by one field (a user tool, not a test).

ParaView 5.11 on Debian renders through GLX only, so run it under a virtual X server:
  xvfb-run -a -s "-screen 0 1024x768x24" pvbatch tools/plot/render_xdmf.py RESULTS.xdmf FIELD OUT.png \
      [--time T | --step K] [--component N|Magnitude] [--size 1024x768]
FIELD is a nodal or element field name (e.g. displacement, stress, block_id); vectors and tensors
are coloured by their magnitude unless --component picks one (0-based). The mesh is drawn as
"Surface With Edges" on the reference coordinates (no warp). Default: the last step.
"""
import argparse
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, Render,
                             SaveScreenshot, Show, XDMFReader)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("xdmf", help="results.xdmf written by tribex (any path; made absolute)")
    p.add_argument("field", help="field to colour by")
    p.add_argument("png", help="output PNG")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--time", type=float, help="time value (s); the nearest step is shown")
    g.add_argument("--step", type=int, help="0-based step index (negative counts from the end)")
    p.add_argument("--component", default="Magnitude", help="component index or Magnitude")
    p.add_argument("--size", default="1024x768", help="image size WxH in pixels")
    a = p.parse_args()

    path = os.path.abspath(a.xdmf)  # Xdmf readers resolve the .h5 wrongly from a bare name
    if not os.path.isfile(path):
        sys.exit(f"error: {a.xdmf}: no such file; pass the results.xdmf of a tribex run")
    try:
        width, height = (int(v) for v in a.size.lower().split("x"))
    except ValueError:
        sys.exit(f"error: --size {a.size}: expected WxH, e.g. 1024x768")

    reader = XDMFReader(FileNames=[path])
    times = list(reader.TimestepValues) or [0.0]
    if a.time is not None:
        t = min(times, key=lambda v: abs(v - a.time))
    else:
        k = -1 if a.step is None else a.step
        if not -len(times) <= k < len(times):
            sys.exit(f"error: --step {k}: the file has {len(times)} steps (0..{len(times) - 1})")
        t = times[k]
    reader.UpdatePipeline(t)

    info = reader.GetDataInformation()
    if reader.PointData.GetArray(a.field) is not None:
        association, array = "POINTS", reader.PointData.GetArray(a.field)
    elif reader.CellData.GetArray(a.field) is not None:
        association, array = "CELLS", reader.CellData.GetArray(a.field)
    else:
        names = list(reader.PointData.keys()) + list(reader.CellData.keys())
        sys.exit(f"error: {path}: no field '{a.field}'; the file has {', '.join(names)}")

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = t
    view.OrientationAxesVisibility = 1
    display = Show(reader, view)
    display.SetRepresentationType("Surface With Edges")
    if array.GetNumberOfComponents() == 1:
        ColorBy(display, (association, a.field))
    elif a.component == "Magnitude":
        ColorBy(display, (association, a.field, "Magnitude"))
    else:
        ColorBy(display, (association, a.field, a.component))
    display.RescaleTransferFunctionToDataRange(False, True)
    display.SetScalarBarVisibility(view, True)
    lut = GetColorTransferFunction(a.field)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    view.CameraPosition = [1, -1.6, 1.2]  # an oblique view from the front-right, z up
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    Render(view)
    SaveScreenshot(a.png, view, ImageResolution=[width, height])
    print(f"{a.png}: {a.field} ({association.lower()}) at t={t:g} s, "
          f"{info.GetNumberOfPoints()} nodes, {info.GetNumberOfCells()} cells")


if __name__ == "__main__":
    main()
