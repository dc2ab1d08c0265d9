#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks of results.exo (tests/output/README.md), run by CTest with Debian's /usr/bin/python3
(netCDF4 and h5py).

  check_exodus.py fields TRIBEX DECK OUT [--ranks N]
      runs DECK (format = both) on N ranks (N > 1: then `tribex join OUT` joins the per-rank results.exo.N.r
      into results.exo), then reads results.exo with netCDF4 and results.h5 with
      h5py: the length unit named in results.exo's info records ("tribex length unit: nm") equal to
      results.h5's `length_unit`; same coordinates (both in that unit, to 1e-12) and connectivity (exactly), block names equal to results.h5's, the
      node and side sets of the generated boxes present and on the right faces; every Exodus time
      equal to results.h5's and every nodal and element variable equal to its results.h5 component
      (the length fields in the same unit in both) within 1e-12 of the field's largest value; every global variable equal to history.csv's column
      at that step within 1e-12 relative. Prints the largest differences.
  check_exodus.py restart TRIBEX DECK OUT --stop STEP [--ranks N]
      uninterrupted run, then a run stopped after STEP and resumed into the same folder: the resumed
      results.exo (N > 1: each rank's results.exo.N.r, then joined; rewritten with the steps before the restart time, then continued) holds the same
      times and bitwise the same values as the uninterrupted one.
  check_exodus.py mesh TRIBEX DECK OUT
      runs DECK (generated boxes) with `length unit = m`, then the same deck on its results.exo as
      `database name = mesh.g`, on a netCDF-4 copy of it (mesh4.g) and on `tribex mesh convert mesh.g
      mesh.msh`: history.csv byte-identical in all four. A deck with `begin surface layer block`s reads
      the unsplit mesh (the results.exo of the deck without them) and splits it at set-up, as it split
      the generated mesh. Then the results.exo the deck writes in its own length unit (nm here): read
      back as a mesh (`tribex mesh convert` to an Exodus file in m) it gives the generated coordinates
      within 2e-16 relative (x 1e9 then / 1e9: round-off, not bitwise).
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys

import h5py
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from tribex_runs import full_and_stopped, run  # noqa: E402

# results.h5 and results.exo hold the coordinates and length fields in the same length unit.

TOL = 1e-12


def names(nc, var):
    """Exodus name arrays (eb_names, name_nod_var, ...) as Python strings."""
    if var not in nc.variables:
        return []
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in nc.variables[var][:].data]


def history(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], {int(float(r[0])): [float(x) for x in r] for r in rows[1:]}


# results.h5 stores the symmetric stress as the full 3x3 row-major tensor.
SYM = {"xx": 0, "yy": 4, "zz": 8, "xy": 1, "yz": 5, "zx": 6}
VEC = {"x": 0, "y": 1, "z": 2}


def h5_component(group, exo_name):
    """The results.h5 column an Exodus variable name stands for, or None."""
    if exo_name in group:
        return group[exo_name][()]
    base, _, suffix = exo_name.rpartition("_")
    if base in group:
        data = group[base][()]
        index = SYM.get(suffix) if data.shape[1] == 9 else VEC.get(suffix)
        return None if index is None else data[:, index]
    return None


def joined(tribex, out, ranks):
    """OUT/results.exo: a parallel run writes OUT/results.exo.N.r, which `tribex join OUT` joins into it."""
    if ranks > 1:
        p = subprocess.run([tribex, "join", out], capture_output=True, text=True)
        if p.returncode != 0:
            sys.exit(f"FAIL: tribex join {out} exited {p.returncode}\n{p.stdout}{p.stderr}")
        print(p.stdout.strip())
    return os.path.join(out, "results.exo")


def fields(a):
    out = a.out
    shutil.rmtree(out, ignore_errors=True)
    run(a.tribex, a.deck, out, a.ranks)
    joined(a.tribex, out, a.ranks)
    exo = netCDF4.Dataset(os.path.join(out, "results.exo"))
    h5 = h5py.File(os.path.join(out, "results.h5"), "r")
    fmt = exo.data_model
    if fmt != "NETCDF3_64BIT_OFFSET":
        sys.exit(f"FAIL: results.exo is {fmt}, expected NETCDF3_64BIT_OFFSET")

    # Mesh: coordinates, connectivity (blocks in element order), names, sets.
    xyz = np.stack([exo.variables[c][:].data for c in ("coordx", "coordy", "coordz")], axis=1)
    # Both files in the length unit the results output chose, named in each.
    info = ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in exo.variables["info_records"][:].data]
    exo_unit = next((line.split(": ", 1)[1] for line in info if line.startswith("tribex length unit: ")), None)
    h5_unit = h5.attrs["length_unit"]
    h5_unit = h5_unit.decode() if isinstance(h5_unit, bytes) else str(h5_unit)
    if exo_unit != h5_unit:
        sys.exit(f"FAIL: results.exo's info records name length unit {exo_unit!r} ({info}), results.h5 {h5_unit!r}")
    print(f"length unit {exo_unit} in both files; results.exo info records: {info}")
    ref_xyz = h5["/mesh/coordinates"][()]
    coordinate_error = np.max(np.abs(xyz - ref_xyz)) / np.max(np.abs(ref_xyz))
    if coordinate_error > TOL:
        sys.exit(f"FAIL: coordinates differ by {coordinate_error:.3g} of the largest")
    nblocks = exo.dimensions["num_el_blk"].size
    conn = np.concatenate([exo.variables[f"connect{b + 1}"][:].data for b in range(nblocks)]) - 1
    if not np.array_equal(conn, h5["/mesh/connectivity"][()]):
        sys.exit("FAIL: connectivity differs")
    block_names = names(exo, "eb_names")
    h5_blocks = h5["/mesh/block_id"].attrs["block_names"]
    h5_blocks = (h5_blocks.decode() if isinstance(h5_blocks, bytes) else str(h5_blocks)).split("\n")
    if block_names != h5_blocks:
        sys.exit(f"FAIL: block names {block_names} != results.h5's {h5_blocks}")
    node_sets, side_sets = names(exo, "ns_names"), names(exo, "ss_names")
    # A surface layer block (mixed blocks) has no sets of its own: its parent's box sets span both.
    parent = dict(re.findall(r"begin surface layer block (\w+)\s+from block = (\w+)", open(a.deck).read()))
    for b in block_names:
        if b in parent:
            continue
        members = {b} | {k for k, v in parent.items() if v == b}
        for face, side in (("xmin", 4), ("xmax", 2), ("ymin", 1), ("ymax", 3), ("zmin", 5), ("zmax", 6)):
            name = f"{b}_{face}"
            if name not in node_sets or name not in side_sets:
                sys.exit(f"FAIL: set {name} missing (node sets {node_sets}, side sets {side_sets})")
            nodes = exo.variables[f"node_ns{node_sets.index(name) + 1}"][:].data - 1
            axis, end = "xyz".index(face[0]), (np.min if face[1:] == "min" else np.max)
            block_nodes = np.unique(conn[[i for i, n in enumerate(h5["/mesh/block_id"][()]) if block_names[n] in members]])
            if not np.all(xyz[nodes, axis] == end(xyz[block_nodes, axis])):
                sys.exit(f"FAIL: node set {name} is not on its face")
            sides = exo.variables[f"side_ss{side_sets.index(name) + 1}"][:].data
            if not np.all(sides == side):
                sys.exit(f"FAIL: side set {name} has sides {set(sides)}, expected Exodus side {side}")
    print(f"mesh: {xyz.shape[0]} nodes, {conn.shape[0]} elements, blocks {block_names}, "
          f"{len(node_sets)} node sets, {len(side_sets)} side sets: equal to results.h5")

    # Steps: times, nodal, element and global variables.
    times = exo.variables["time_whole"][:].data
    steps = sorted(h5["/steps"].keys())
    if len(times) != len(steps) or len(times) < 2:
        sys.exit(f"FAIL: {len(times)} Exodus times, {len(steps)} results.h5 steps")
    nodal, element, globals_ = names(exo, "name_nod_var"), names(exo, "name_elem_var"), names(exo, "name_glo_var")
    header, rows = history(os.path.join(out, "history.csv"))
    if globals_ != header:
        sys.exit(f"FAIL: global variables {globals_} != history.csv columns {header}")
    worst = {"nodal": 0.0, "element": 0.0, "global": 0.0}
    block_sizes = [exo.dimensions[f"num_el_in_blk{b + 1}"].size for b in range(nblocks)]
    for k, step in enumerate(steps):
        g = h5["/steps"][step]
        if times[k] != g.attrs["time"]:
            sys.exit(f"FAIL: step {k}: Exodus time {times[k]!r} != results.h5 {g.attrs['time']!r}")
        for v, name in enumerate(nodal):
            ref = h5_component(g["nodal"], name)
            if ref is None:
                sys.exit(f"FAIL: nodal variable {name} has no results.h5 field")
            got = exo.variables[f"vals_nod_var{v + 1}"][k, :].data
            scale = max(np.max(np.abs(ref)), 1e-300)
            worst["nodal"] = max(worst["nodal"], np.max(np.abs(got - ref)) / scale)
        for v, name in enumerate(element):
            ref = h5_component(g["element"], name)
            if ref is None:
                sys.exit(f"FAIL: element variable {name} has no results.h5 field")
            got = np.concatenate([exo.variables[f"vals_elem_var{v + 1}eb{b + 1}"][k, :].data for b in range(nblocks)])
            scale = max(np.max(np.abs(ref)), 1e-300)
            worst["element"] = max(worst["element"], np.max(np.abs(got - ref)) / scale)
        values = exo.variables["vals_glo_var"][k, :].data
        row = rows.get(int(values[0]))
        if row is None:
            sys.exit(f"FAIL: no history.csv row for step {values[0]}")
        for j, name in enumerate(globals_):
            diff = abs(values[j] - row[j]) / max(abs(row[j]), 1e-300)
            worst["global"] = max(worst["global"], diff if row[j] != 0 else abs(values[j]))
    print(f"{len(times)} steps; variables: nodal {nodal}, element {element}, {len(globals_)} global; block sizes {block_sizes}")
    print("largest difference Exodus vs results.h5 / history.csv (relative to the field's largest value): " +
          ", ".join(f"{k} {v:.3g}" for k, v in worst.items()))
    if max(worst.values()) > TOL:
        sys.exit(f"FAIL: a difference above {TOL}")
    print(f"results.exo {os.path.getsize(os.path.join(out, 'results.exo'))} bytes, results.h5 "
          f"{os.path.getsize(os.path.join(out, 'results.h5'))} bytes")
    print("PASS")


def all_values(path):
    exo = netCDF4.Dataset(path)
    return {k: v[:].data.copy() for k, v in exo.variables.items()}


def restart(a):
    full, stopped = full_and_stopped(a.tribex, a.deck, a.out, a.ranks, a.stop, "stopped")
    first = "results.exo" if a.ranks == 1 else f"results.exo.{a.ranks}.{0:0{len(str(a.ranks))}d}"
    before = len(all_values(os.path.join(stopped, first))["time_whole"])
    run(a.tribex, a.deck, stopped, a.ranks, "--restart", os.path.join(stopped, "restart.h5"))
    # In parallel each rank's file is rewritten and continued; the joined files must then be equal.
    want, got = all_values(joined(a.tribex, full, a.ranks)), all_values(joined(a.tribex, stopped, a.ranks))
    if sorted(want) != sorted(got):
        sys.exit(f"FAIL: variables differ: {sorted(set(want) ^ set(got))}")
    for k in want:
        if want[k].shape != got[k].shape or not np.array_equal(want[k], got[k]):
            sys.exit(f"FAIL: {k} differs after the restart ({want[k].shape} vs {got[k].shape})")
    print(f"stopped run wrote {before} steps (the last at the stop); resumed results.exo: {len(want['time_whole'])} "
          "steps, every variable bitwise equal to the uninterrupted run's")
    print("PASS")


def to_netcdf4(source, target):
    """A copy of a netCDF-3 file in NETCDF4_CLASSIC (what Exodus writes with EX_NETCDF4)."""
    with netCDF4.Dataset(source) as src, netCDF4.Dataset(target, "w", format="NETCDF4_CLASSIC") as dst:
        dst.setncatts({k: src.getncattr(k) for k in src.ncattrs()})
        for name, dim in src.dimensions.items():
            dst.createDimension(name, None if dim.isunlimited() else len(dim))
        for name, var in src.variables.items():
            out = dst.createVariable(name, var.dtype if var.dtype != np.dtype("S1") else "S1", var.dimensions)
            out.setncatts({k: var.getncattr(k) for k in var.ncattrs()})
            var.set_auto_maskandscale(False)
            out.set_auto_maskandscale(False)
            out[:] = var[:]


def mesh(a):
    gen = os.path.join(a.out, "generated")
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    native = open(a.deck).read()
    # The bitwise checks read a file in metres: the deck's results in m.
    text = re.sub(r"(begin results output \w+)", r"\1\n        length unit = m", native, count=1)
    in_metres = os.path.join(a.out, "in_metres.i")
    with open(in_metres, "w") as f:
        f.write(text)
    a = argparse.Namespace(**{**vars(a), "deck": in_metres})
    run(a.tribex, a.deck, gen)
    # Mixed blocks: the mesh file is the unsplit mesh (a run without the surface layer blocks), which
    # the deck then splits at set-up, as it splits the generated one.
    skins = re.findall(r"begin surface layer block (\w+)", text)
    source = gen
    if skins:
        source = os.path.join(a.out, "unsplit")
        unsplit = text
        for name in skins:
            for block in ("surface layer block", "parameters for block"):
                unsplit = re.sub(rf"\n\s*begin {block} {name}\b.*?end {block} {name}", "", unsplit, flags=re.S)
        with open(os.path.join(a.out, "unsplit.i"), "w") as f:
            f.write(unsplit)
        run(a.tribex, os.path.join(a.out, "unsplit.i"), source)
    shutil.copy(os.path.join(source, "results.exo"), os.path.join(a.out, "mesh.g"))
    p = subprocess.run([a.tribex, "mesh", "convert", os.path.join(a.out, "mesh.g"), os.path.join(a.out, "mesh.msh")],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"FAIL: tribex mesh convert exited {p.returncode}\n{p.stdout}{p.stderr}")
    # The same mesh as netCDF-4 (HDF5 inside, as Cubit may write it): read by tribex through the Open
    # MPI HDF5 of libnetcdf_mpi, in the process that then writes results.h5 with the same HDF5.
    to_netcdf4(os.path.join(a.out, "mesh.g"), os.path.join(a.out, "mesh4.g"))
    # The generated boxes give way to the mesh file (the deck's block and set names are its names).
    text = re.sub(r"\n\s*begin generated box (\w+).*?end generated box \1", "", text, flags=re.S)
    reference = open(os.path.join(gen, "history.csv"), "rb").read()
    for mesh_file in ("mesh.g", "mesh4.g", "mesh.msh"):
        deck = os.path.join(a.out, f"from_{mesh_file.replace('.', '_')}.i")
        with open(deck, "w") as f:
            f.write(re.sub(r"(begin finite element model \w+)", rf"\1\n    database name = {mesh_file}", text, count=1))
        out = os.path.join(a.out, mesh_file.replace(".", "_"))
        run(a.tribex, deck, out)
        if open(os.path.join(out, "history.csv"), "rb").read() != reference:
            sys.exit(f"FAIL: the run on {mesh_file} has another history.csv than the run on the generated mesh")
        print(f"run on {mesh_file}: history.csv byte-identical to the generated mesh's")
    unit_round_trip(a, native)
    print("PASS")


def unit_round_trip(a, native):
    """results.exo in the deck's own length unit, read back as a mesh: the coordinates in m again."""
    out = os.path.join(a.out, "native")
    deck = os.path.join(a.out, "native.i")
    with open(deck, "w") as f:
        f.write(native)
    run(a.tribex, deck, out)
    with netCDF4.Dataset(os.path.join(out, "results.exo")) as exo:
        info = names(exo, "info_records")
    converted = os.path.join(a.out, "native_in_m.exo")
    p = subprocess.run([a.tribex, "mesh", "convert", os.path.join(out, "results.exo"), converted],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"FAIL: tribex mesh convert exited {p.returncode}\n{p.stdout}{p.stderr}")
    with netCDF4.Dataset(converted) as exo:
        xyz = np.stack([exo.variables[c][:].data for c in ("coordx", "coordy", "coordz")], axis=1)
    with h5py.File(os.path.join(a.out, "generated", "results.h5"), "r") as h5:
        ref = h5["/mesh/coordinates"][()]  # the generated mesh in m (the metre run)
    error = np.max(np.abs(xyz - ref)) / np.max(np.abs(ref))
    print(f"results.exo in its own unit ({info[0] if info else 'no info records'}), read back as a mesh in m: "
          f"coordinates within {error:.2g} of the largest (tolerance 2e-16)")
    if not (info and info[0].startswith("tribex length unit: ")) or error > 2e-16:
        sys.exit("FAIL: the length unit is not named first in the info records, or the coordinates differ")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode", choices=["fields", "restart", "mesh"])
    p.add_argument("tribex")
    p.add_argument("deck")
    p.add_argument("out")
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--stop", type=int, default=0)
    a = p.parse_args()
    {"fields": fields, "restart": restart, "mesh": mesh}[a.mode](a)


if __name__ == "__main__":
    main()
