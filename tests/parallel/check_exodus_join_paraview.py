# SPDX-License-Identifier: MIT
"""ParaView 5.11 opens a parallel run's Exodus output (CTest mpi_exodus_join_paraview, run by pvbatch with
DISPLAY unset: reading needs no X server, as output_exodus_paraview). Usage:

  pvbatch check_exodus_join_paraview.py SERIAL/results.exo PARALLEL_OUT RANKS [RTOL]

With each of ParaView's Exodus readers (IOSSReader, the default for .exo, and the legacy ExodusIIReader),
opens the serial run's results.exo, the parallel run's per-rank files (PARALLEL_OUT/results.exo.N.0: the
readers find the other ranks' files of the spread themselves) and the joined PARALLEL_OUT/results.exo,
merges the blocks, and at every time step compares the point and cell arrays: the same names, the same
number of points (after the merge: the shared nodes once) and cells, and, sorted by global id (IOSS
`ids`, ExodusII GlobalNodeId/GlobalElementId), the per-rank set's values equal to the joined file's
bitwise and both within RTOL (1e-10) of the serial file's, relative to the array's largest value.
"""
import os
import sys

import numpy as np
from paraview import servermanager as sm
from paraview.simple import Delete, ExodusIIReader, IOSSReader, MergeBlocks
from vtk.numpy_interface import dataset_adapter as dsa

SKIP = ("PedigreeNodeId", "PedigreeElementId")  # the reader's own local numbering


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def open_reader(kind, path):
    if kind == "IOSSReader":
        r = IOSSReader(FileName=[path])
    else:
        r = ExodusIIReader(FileName=[path])
        r.UpdatePipelineInformation()
        r.PointVariables = list(r.PointVariables.Available)
        r.ElementVariables = list(r.ElementVariables.Available)
        r.GenerateGlobalNodeIdArray = 1
        r.GenerateGlobalElementIdArray = 1
    r.UpdatePipelineInformation()
    return r, MergeBlocks(Input=r)


def sorted_arrays(merge, time, ids, what):
    """{name: values sorted by global id} of the point and cell data at `time`; a point the merge kept twice
    (a shared node in two rank files) must carry the same values in both copies."""
    merge.UpdatePipeline(time)
    d = dsa.WrapDataObject(sm.Fetch(merge))
    out = {}
    for kind, data, key in (("point", d.PointData, ids[0]), ("cell", d.CellData, ids[1])):
        gid = np.asarray(data[key])
        order = np.argsort(gid, kind="stable")
        unique, first = np.unique(gid[order], return_index=True)
        for name in data.keys():
            if name in SKIP:
                continue
            v = np.asarray(data[name])[order]
            kept = v[first]
            again = np.repeat(kept, np.diff(np.append(first, len(v))), axis=0)
            if not np.array_equal(again, v, equal_nan=True):
                fail(f"{what}: {kind} array {name}: two copies of a shared node or cell differ")
            out[(kind, name)] = kept
        out[(kind, "#")] = len(unique)
    return out


def compare(kind, serial, spread, joined, rtol):
    times = serial[0].TimestepValues
    for name, r in (("per-rank files", spread[0]), ("joined file", joined[0])):
        if list(r.TimestepValues) != list(times):
            fail(f"{kind}, {name}: time steps {list(r.TimestepValues)} where the serial file has {list(times)}")
    ids = ("ids", "ids") if kind == "IOSSReader" else ("GlobalNodeId", "GlobalElementId")
    worst = 0.0
    for t in times:
        s = sorted_arrays(serial[1], t, ids, f"{kind}, serial")
        p = sorted_arrays(spread[1], t, ids, f"{kind}, per-rank files")
        j = sorted_arrays(joined[1], t, ids, f"{kind}, joined file")
        for name, got in (("per-rank files", p), ("joined file", j)):
            if sorted(got) != sorted(s):
                fail(f"{kind}, {name} at t = {t}: arrays {sorted(set(got) ^ set(s))} differ from the serial file's")
        for key, want in s.items():
            if key[1] == "#":
                if p[key] != want or j[key] != want:
                    fail(f"{kind} at t = {t}: {p[key]} / {j[key]} {key[0]}s (per-rank / joined), serial {want}")
                continue
            if not np.array_equal(p[key], j[key], equal_nan=True):
                fail(f"{kind} at t = {t}: {key[0]} array {key[1]} of the per-rank files is not the joined file's")
            scale = float(np.nanmax(np.abs(want))) if want.size else 0.0
            d = float(np.nanmax(np.abs(p[key] - want))) if want.size else 0.0
            rel = d / scale if scale > 0 else d
            if rel > rtol or not np.array_equal(np.isnan(p[key]), np.isnan(want)):
                fail(f"{kind} at t = {t}: {key[0]} array {key[1]} differs from the serial file's by {rel:.3g} (> {rtol})")
            worst = max(worst, rel)
    names = sorted(k[1] for k in s if k[1] != "#")
    print(f"{kind}: serial, per-rank and joined files: {len(times)} steps, {s[('point', '#')]} points, "
          f"{s[('cell', '#')]} cells, arrays {names}; per-rank = joined bitwise, largest difference from the serial "
          f"file {worst:.3g} of the array's largest value")


def main():
    serial_path, out, ranks = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), int(sys.argv[3])
    rtol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-10
    first = os.path.join(out, f"results.exo.{ranks}.{0:0{len(str(ranks))}d}")
    for kind in ("IOSSReader", "ExodusIIReader"):
        readers = [open_reader(kind, p) for p in (serial_path, first, os.path.join(out, "results.exo"))]
        compare(kind, *readers, rtol)
        for r, m in readers:
            Delete(m)
            Delete(r)
    print("PASS")


if __name__ == "__main__":
    main()
