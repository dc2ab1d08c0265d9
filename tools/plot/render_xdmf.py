# SPDX-License-Identifier: MIT
"""Render a PNG of a tribex results.xdmf coloured by one field (a user tool; tests/output renders with it).

ParaView 5.11 on Debian renders through GLX only, so run it under a virtual X server:
  xvfb-run -a -s "-screen 0 1024x768x24" pvbatch tools/plot/render_xdmf.py RESULTS.xdmf [FIELD] OUT.png \\
      [--time T | --step K] [--component N|Magnitude] [--view contact|top|whole] [--warp S] [--edges] [--size WxH]
FIELD: a nodal or element field (displacement, stress, contact_traction, block_id, ...; the unit
ParaView shows in brackets may be left out) or von_mises (from stress); default von_mises when the
file has stress, else displacement. Vectors and tensors are coloured by their magnitude unless
--component picks one (0-based).
Defaults: the step with the most nodes in contact (the last step when the file has no
contact_status); the body deformed by its displacement (Warp By Vector, scale 1: the geometry and
the displacement are in the same length unit); --view contact when that step has contact: the
section through the contact centre normal to y, seen from -y (x to the right, z up), framed on the
contact region; else --view whole, an oblique view of the whole body. --view top: the contact
pressure seen along z (x to the right): the block that holds the slave nodes in contact (the lower
one when both do), seen from above (from below for an upper block, y then pointing down), framed
on the contact region; its default field is contact_pressure (a nodal variable of the run). Files written before the length unit (SI
coordinates) are scaled to nm here when the model is under 1 um, since ParaView renders noise at
coordinates of 1e-8 (issue 27).
Prints one line: the PNG, field, step, time, view, and the colour range with its unit.
"""
import argparse
import builtins  # pvbatch may run scripts with numpy's max/min in scope
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np
from paraview.simple import (CellDatatoPointData, Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, MergeBlocks, ProgrammableFilter, Render, SaveScreenshot, Show, Threshold,
                             Transform, WarpByVector, XDMFReader)

PER_METRE = {"m": 1.0, "um": 1e6, "nm": 1e9}

# von Mises stress of a 9-component row-major tensor array, per cell (a ProgrammableFilter script).
VON_MISES = """
import numpy as np
from vtk.numpy_interface import dataset_adapter as dsa
data = dsa.WrapDataObject(self.GetInputDataObject(0, 0))
out = dsa.WrapDataObject(self.GetOutputDataObject(0))
s = np.asarray(data.CellData[{name!r}]).reshape(-1, 9)
vm = np.sqrt(0.5 * ((s[:, 0] - s[:, 4]) ** 2 + (s[:, 4] - s[:, 8]) ** 2 + (s[:, 8] - s[:, 0]) ** 2)
             + 3.0 * (s[:, 1] ** 2 + s[:, 5] ** 2 + s[:, 2] ** 2))
out.CellData.append(vm, "von_mises")
"""


def xdmf_facts(path):
    """(length unit, h5 file, {field: (ParaView name, unit, nodal?)}) from the XDMF text."""
    root = ET.parse(path).getroot()
    unit = "m"  # files written before the length unit were SI
    for info in root.iter("Information"):
        if info.get("Name") == "length_unit":
            unit = info.get("Value", "m")
    fields, h5 = {}, None
    for attr in root.iter("Attribute"):
        shown = attr.get("Name")
        # The unit: the attribute's <Information Name="units">; files before it put it in the name.
        m = re.fullmatch(r"(.*?) \[(.*)\]", shown)
        base, field_unit = (m.group(1), m.group(2)) if m else (shown, "")
        for info in attr.iter("Information"):
            if info.get("Name") == "units":
                field_unit = info.get("Value", "")
        fields.setdefault(base, (shown, field_unit, attr.get("Center") == "Node"))
    for item in root.iter("DataItem"):
        if item.get("Format") == "HDF" and item.text and ":" in item.text:
            h5 = os.path.join(os.path.dirname(path), item.text.strip().split(":")[0])
            break
    return unit, h5, fields


def contact_steps(h5_path):
    """Per step: nodes in contact, or None when the file has no contact_status (or no h5py)."""
    try:
        import h5py
    except ImportError:
        return None
    with h5py.File(h5_path, "r") as f:
        steps = sorted(f["steps"])
        if not steps or "contact_status" not in f["steps"][steps[0]].get("nodal", {}):
            return None
        return [int(np.count_nonzero(f["steps"][s]["nodal"]["contact_status"][()] > 0)) for s in steps]


def contact_region(h5_path, step, geometry_scale):
    """Centre (deformed, in the picture's length unit) and radius of the nodes in contact at step k."""
    import h5py
    with h5py.File(h5_path, "r") as f:
        name = sorted(f["steps"])[step]
        nodal = f["steps"][name]["nodal"]
        x = f["mesh/coordinates"][()]
        if "displacement" in nodal:
            u = nodal["displacement"]
            # Displacement is in the file's length unit; a file without units attributes is SI like x.
            x = x + u[()]
        on = nodal["contact_status"][()] > 0
        pts = x[on] * geometry_scale
    centre = pts.mean(axis=0)
    radius = float(np.max(np.hypot(pts[:, 0] - centre[0], pts[:, 1] - centre[1]))) if len(pts) > 1 else 0.0
    return centre, radius


def slave_block(h5_path, step):
    """(block id, True when it lies below the contact) of the block holding the nodes in contact at step
    k, the lowest one (by mean z of its nodes in contact) when several do."""
    import h5py
    with h5py.File(h5_path, "r") as f:
        nodal = f["steps"][sorted(f["steps"])[step]]["nodal"]
        on = nodal["contact_status"][()] > 0
        x = f["mesh/coordinates"][()]
        if "displacement" in nodal:
            x = x + nodal["displacement"][()]
        conn, block = f["mesh/connectivity"][()], f["mesh/block_id"][()]
    best = None
    for b in np.unique(block[block >= 0]):
        nodes = np.unique(conn[block == b])
        touching = nodes[on[nodes]]
        if len(touching) == 0:
            continue
        z = x[touching, 2].mean()
        if best is None or z < best[1]:
            best = (int(b), z, x[nodes, 2].mean() <= z)
    return (best[0], best[2]) if best else (None, True)


def cut_for_view(source, view_kind, centre, h5_path, k):
    """(the filtered source, seen from below?): contact, the half body y >= y_c (its cut face seen from
    -y, x to the right); top, the block holding the slave nodes in contact (from below when it is the
    upper one); whole, the source as it is."""
    if view_kind == "contact":
        clip = Clip(Input=source)
        clip.ClipType = "Plane"
        clip.ClipType.Origin = list(centre)
        clip.ClipType.Normal = [0.0, 1.0, 0.0]
        clip.Invert = 0
        return clip, False
    if view_kind == "top":
        block, below = slave_block(h5_path, k)
        if block is not None:
            only = Threshold(Input=source)  # the slave block alone: its contact face unhidden
            only.Scalars = ["CELLS", "block_id"]
            only.LowerThreshold = only.UpperThreshold = block
            source = only
        return source, not below
    return source, False


def frame(view, view_kind, centre, radius, extent, from_below):
    """The camera. Contact and top views: framed on the contact region (half height 3 contact radii,
    at least 8 % of the model); right-handed screens: seen from -y with z up, from +z with y up, from
    -z with y down, so x points right in each. Whole: an oblique view from the front-right, z up."""
    view.CameraViewUp = [0, 0, 1]
    if view_kind in ("contact", "top"):
        view.CameraParallelProjection = 1
        view.CameraFocalPoint = list(centre)
        if view_kind == "contact":
            view.CameraPosition = [centre[0], centre[1] - 4.0 * extent, centre[2]]
        else:
            view.CameraPosition = [centre[0], centre[1], centre[2] + (-4.0 if from_below else 4.0) * extent]
            view.CameraViewUp = [0, -1, 0] if from_below else [0, 1, 0]
        view.CameraParallelScale = builtins.max(3.0 * radius, 0.08 * extent)
    else:
        view.CameraPosition = [1, -1.6, 1.2]
        view.ResetCamera()


def colour(display, view, source, array, component_arg, field, field_unit, where):
    """Colours `display` by `array` (association, name) with Viridis and a titled colour bar (unit,
    range); returns (bar, lo, hi)."""
    association, colour_name = array
    array_info = (source.PointData if association == "POINTS" else source.CellData).GetArray(colour_name)
    if array_info is None:
        sys.exit(f"error: {where}: field '{colour_name}' not found")
    if array_info.GetNumberOfComponents() == 1:
        ColorBy(display, (association, colour_name))
        component = None
    elif component_arg == "Magnitude":
        ColorBy(display, (association, colour_name, "Magnitude"))
        component = -1
    else:
        component = int(component_arg)
        ColorBy(display, (association, colour_name, str(component)))
    lo, hi = array_info.GetRange(-1 if component is None else component)
    lut = GetColorTransferFunction(colour_name)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    if component is not None and component >= 0:
        lut.VectorMode, lut.VectorComponent = "Component", component
    display.RescaleTransferFunctionToDataRange(False, True)
    if component == -1 or component is None:
        lo, hi = lut.RGBPoints[0], lut.RGBPoints[-4]
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    title = "von Mises stress" if field == "von_mises" else field.replace("_", " ")
    what = "" if component is None else (" magnitude" if component == -1 else f" component {component}")
    bar.Title = title + what + (f" [{field_unit}]" if field_unit and field_unit != "1" else "")
    bar.ComponentTitle = ""  # else ParaView appends "Magnitude" or the component index
    bar.RangeLabelFormat = "%-#.3g"
    bar.LabelFormat = "%-#.3g"
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize, bar.LabelFontSize = 18, 16
    bar.ScalarBarLength = 0.4
    bar.WindowLocation = "Upper Right Corner"  # in the contact view the gap beside the tip stays white there
    return bar, lo, hi


def parse_args():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("xdmf", help="results.xdmf written by tribex (any path; made absolute)")
    p.add_argument("field", nargs="?", help="field to colour by (default von_mises, or displacement)")
    p.add_argument("png", help="output PNG")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--time", type=float, help="time value (s); the nearest step is shown")
    g.add_argument("--step", type=int, help="0-based step index (negative counts from the end)")
    p.add_argument("--component", default="Magnitude", help="component index or Magnitude")
    p.add_argument("--view", choices=["contact", "top", "whole"],
                   help="framing (default: contact when there is contact); top: the contact pressure from above")
    p.add_argument("--warp", type=float, default=1.0, help="displacement scale of the deformed shape (0: undeformed)")
    p.add_argument("--edges", action="store_true", help="draw the element edges")
    p.add_argument("--size", default="1024x768", help="image size WxH in pixels")
    return p.parse_args()


def main():
    a = parse_args()

    path = os.path.abspath(a.xdmf)  # Xdmf readers resolve the .h5 wrongly from a bare name
    if not os.path.isfile(path):
        sys.exit(f"error: {a.xdmf}: no such file; pass the results.xdmf of a tribex run")
    try:
        width, height = (int(v) for v in a.size.lower().split("x"))
    except ValueError:
        sys.exit(f"error: --size {a.size}: expected WxH, e.g. 1024x768")
    unit, h5_path, fields = xdmf_facts(path)
    if a.view == "top" and not a.field and "contact_pressure" not in fields:
        sys.exit(f"error: {path}: --view top shows contact_pressure, which the run did not write; add it to "
                 "the deck's 'nodal variables' (or name another FIELD)")
    default = "contact_pressure" if a.view == "top" else ("von_mises" if "stress" in fields else "displacement")
    field = a.field or default
    field = re.sub(r" \[.*\]$", "", field)
    if field != "von_mises" and field not in fields and field != "block_id":
        sys.exit(f"error: {path}: no field '{field}'; the file has {', '.join(sorted(fields))}, von_mises")
    if field == "von_mises" and "von_mises" not in fields and "stress" not in fields:
        sys.exit(f"error: {path}: von_mises needs the stress field; the file has {', '.join(sorted(fields))}")

    reader = XDMFReader(FileNames=[path])
    times = list(reader.TimestepValues) or [0.0]
    in_contact = contact_steps(h5_path) if h5_path and os.path.isfile(h5_path) else None
    if a.time is not None:
        k = builtins.min(range(len(times)), key=lambda i: abs(times[i] - a.time))
    elif a.step is not None:
        if not -len(times) <= a.step < len(times):
            sys.exit(f"error: --step {a.step}: the file has {len(times)} steps (0..{len(times) - 1})")
        k = a.step % len(times)
    elif in_contact and builtins.max(in_contact) > 0:
        k = int(np.argmax(in_contact))  # the deepest contact: the first step with the most nodes in it
    else:
        k = len(times) - 1
    t = times[k]

    # One grid per block in the file: merged (coincident nodes merged, so each node once) for the
    # filters below; the block name stays readable as block_id.
    source = MergeBlocks(Input=reader)
    source.UpdatePipeline(t)
    bounds = source.GetDataInformation().GetBounds()
    extent = builtins.max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    # Old SI files of a nanometre model: scale to nm, geometry and displacement together.
    scale = 1e9 if unit == "m" and 0 < extent < 1e-6 else 1.0
    shown_unit = "nm" if scale != 1.0 else unit
    if scale != 1.0:
        source = Transform(Input=source)
        source.Transform.Scale = [scale] * 3
        source.TransformAllInputVectors = 1  # the displacement too
        extent *= scale

    # Deformed shape first: CellDatatoPointData below passes no point arrays on.
    if a.warp != 0.0 and "displacement" in fields:
        source = WarpByVector(Input=source)
        source.Vectors = ["POINTS", fields["displacement"][0]]
        source.ScaleFactor = a.warp

    colour_name, association = None, None
    if field == "von_mises" and "von_mises" not in fields:  # files without the von_mises field
        vm = ProgrammableFilter(Input=source)
        vm.Script = VON_MISES.format(name=fields["stress"][0])
        source, colour_name, association, field_unit = vm, "von_mises", "CELLS", fields["stress"][1] or "Pa"
    elif field == "block_id":
        colour_name, association, field_unit = "block_id", "CELLS", ""
    else:
        colour_name, field_unit = fields[field][0], fields[field][1]
        association = "POINTS" if fields[field][2] else "CELLS"
    if association == "CELLS" and field != "block_id":
        source = CellDatatoPointData(Input=source)  # smooth colours across element faces
        source.PassCellData = 0
        association = "POINTS"

    view_kind = a.view
    centre, radius = None, 0.0
    if in_contact and in_contact[k] > 0:
        centre, radius = contact_region(h5_path, k, (PER_METRE[shown_unit] / PER_METRE[unit]))
    if view_kind is None:
        view_kind = "contact" if centre is not None else "whole"
    if view_kind in ("contact", "top") and centre is None:
        sys.exit(f"error: --view {view_kind}: step {k} has no node in contact")

    source, from_below = cut_for_view(source, view_kind, centre, h5_path, k)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = t
    view.OrientationAxesVisibility = 1
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0  # ParaView 5.11: else the palette overrides Background
    except AttributeError:
        pass
    display = Show(source, view)
    display.SetRepresentationType("Surface With Edges" if a.edges else "Surface")
    source.UpdatePipeline(t)
    bar, lo, hi = colour(display, view, source, (association, colour_name), a.component, field, field_unit,
                         f"{path} at step {k}")

    Render(view)  # the first render resets the camera: frame the picture after it
    frame(view, view_kind, centre, radius, extent, from_below)
    Render(view)
    SaveScreenshot(a.png, view, ImageResolution=[width, height], TransparentBackground=0)
    info = source.GetDataInformation()
    # The screen's right-hand direction, (focal point - camera) x view up: where the x axis points.
    look = np.subtract(view.CameraFocalPoint, view.CameraPosition)
    right = np.cross(look, view.CameraViewUp)
    x_side = "x to the right" if right[0] > 0.5 * np.linalg.norm(right) else "x NOT to the right"
    print(f"{a.png}: {bar.Title} at step {k}, t={t:g} s, view {view_kind} ({x_side}), lengths in {shown_unit}"
          + (f", contact radius {radius:.3g} {shown_unit}" if centre is not None else "")
          + f"; colour range {lo:.4g} .. {hi:.4g}; {info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells shown")


if __name__ == "__main__":
    main()
