#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes a crafted copy of a netCDF classic Exodus II file (tests/bounds/cases.sh, issue 54 items 11, 16).

usage: craft_exodus.py SRC DST elements|name_length|cut|not_exodus
  elements:    the header's num_elem dimension set to 2,000,000,000
  name_length: the global attribute maximum_name_length set to 2,000,000,000
  cut:         the first half of the file
  duplicate_dimension: dimension num_nod_ns9 renamed num_nod_ns8 (the first fuzz finding: the libraries
               misread it and read_exodus crashed)
  nul_in_name: dimension num_node_sets renamed 'num_nodes\\0\\0_s' (the second fuzz finding, 2026-11-29: the C
               libraries end the name at the NUL, see two dimensions 'num_nodes', and ex_get_coord wrote 363
               coordinates into 14 places)
  coord_dimension: coordx declared over a new dimension 100 x num_nodes (the library filled a num_nodes buffer
               from it: a segmentation fault before the header walk checked the variables' dimensions)
  attribute_values: the global attribute int64_status with 141 values (ex_open reads it into one int on its
               stack: "stack smashing detected", the third fuzz finding)
  copy:        SRC unchanged (with _nc4: the same mesh as a netCDF-4 file)
  KIND_nc4:    coord_dimension, attribute_values or copy written as netCDF-4 (HDF5), which the classic walk does
               not read: checked through the netCDF library (mesh/exodus_shapes.cpp check_netcdf4_exodus)
  not_exodus:  a netCDF classic file with one dimension and variable, no Exodus structure (SRC unused)
"""
import struct
import sys


def patch(data, marker, skip, value):
    at = data.find(marker)
    if at < 0:
        sys.exit(f"craft_exodus.py: {marker!r} not found")
    at += len(marker) + skip
    return data[:at] + struct.pack(">i", value) + data[at + 4:]


src, dst, kind = sys.argv[1:4]
if kind == "not_exodus":
    import netCDF4
    with netCDF4.Dataset(dst, "w", format="NETCDF3_64BIT_OFFSET") as f:
        f.createDimension("x", 4)
        f.createVariable("temperature", "f8", ("x",))[:] = [1.0, 2.0, 3.0, 4.0]
    sys.exit(0)
def rewrite(src, dst, wide_coordx=False, attributes=None, file_format=None):
    """A copy of the netCDF file SRC through the netCDF library, coordx declared over a new dimension of
    100 x num_nodes values (wide_coordx), global attributes replaced by `attributes`, in `file_format`
    (default: SRC's)."""
    import netCDF4
    import numpy
    with netCDF4.Dataset(src) as f, netCDF4.Dataset(dst, "w", format=file_format or f.file_format) as g:
        wide = 100 * len(f.dimensions["num_nodes"])
        for name, d in f.dimensions.items():
            g.createDimension(name, None if d.isunlimited() else len(d))
        g.createDimension("num_nodes_wide", wide)
        g.setncatts({**{k: f.getncattr(k) for k in f.ncattrs()}, **(attributes or {})})
        for name, v in f.variables.items():
            widened = wide_coordx and name == "coordx"
            w = g.createVariable(name, v.dtype, ("num_nodes_wide",) if widened else v.dimensions)
            w.setncatts({k: v.getncattr(k) for k in v.ncattrs()})
            v.set_auto_mask(False)
            values = numpy.resize(v[:], wide) if widened else v[:]
            if values.size:
                w[:] = values


netcdf4 = kind.endswith("_nc4")
kind = kind.removesuffix("_nc4")
if kind in ("coord_dimension", "attribute_values", "copy"):
    import numpy
    rewrite(src, dst, wide_coordx=kind == "coord_dimension",
            attributes={"int64_status": numpy.arange(141, dtype="i4")} if kind == "attribute_values" else None,
            file_format="NETCDF4" if netcdf4 else None)
    sys.exit(0)
data = open(src, "rb").read()
if kind == "elements":
    data = patch(data, b"\x00\x00\x00\x08num_elem", 0, 2_000_000_000)
elif kind == "name_length":
    data = patch(data, b"\x00\x00\x00\x13maximum_name_length\x00", 8, 2_000_000_000)
elif kind == "duplicate_dimension":
    marker = b"\x00\x00\x00\x0bnum_nod_ns9"
    if marker not in data:
        sys.exit("craft_exodus.py: no dimension num_nod_ns9")
    data = data.replace(marker, b"\x00\x00\x00\x0bnum_nod_ns8", 1)
elif kind == "nul_in_name":
    marker = b"\x00\x00\x00\x0dnum_node_sets"
    if marker not in data:
        sys.exit("craft_exodus.py: no dimension num_node_sets")
    data = data.replace(marker, b"\x00\x00\x00\x0dnum_nodes\x00\x00_s", 1)
elif kind == "cut":
    data = data[: len(data) // 2]
open(dst, "wb").write(data)
