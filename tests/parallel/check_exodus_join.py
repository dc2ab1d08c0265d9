#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Per-rank results.exo.N.r and `tribex join` (solver/output/README.md "Exodus II output"), run by CTest
with Debian's /usr/bin/python3 (netCDF4).

  check_exodus_join.py agree TRIBEX DECK OUT --ranks N [--distributed] [--termination T] [--increment T]
      DECK with `format = exodus` (and the termination time and results time increment given) runs on one
      rank (OUT/serial) and on N (OUT/npN: one file per rank, no results.exo); `tribex join OUT/npN`
      writes OUT/npN/results.exo, which must equal OUT/serial/results.exo: the same dimensions and
      variable names, coordinates, connectivity, block names and node sets bitwise, side sets as the
      same (element, side) pairs (the join orders them by element), the times bitwise, and every nodal,
      element and global variable within RTOL (1e-10) of the largest value of its field (a vector's or
      tensor's components share one scale: a shear component at round-off level is compared to the
      stress it belongs to; the global variables, the history columns, likewise: momentum_x/_y/_z share
      one scale); the global variable names are history.csv's columns, whole. --distributed: `set-up = distributed` (each rank generates its slab), and
      log.txt must show it did not fall back to the serial set-up. --open-files K: the join runs with
      `ulimit -n` K (RLIMIT_NOFILE), fewer descriptors than rank files.
  check_exodus_join.py segments TRIBEX DECK OUT --from-ranks N --ranks M --stop STEP
      DECK on N ranks stopped after STEP, resumed on M ranks into the same folder; `tribex join` on it (no
      --ranks: the manifest's run segments) must equal the uninterrupted M-rank run's joined file (times and
      mesh bitwise, variables within RTOL of their field's largest value).
  check_exodus_join.py bad TRIBEX DECK OUT --ranks N
      OUT/npN of an agree run: `tribex join` on a copy without rank 1's file, on a copy with rank 1's file
      cut to half and to all but its last 64 bytes, and on a copy holding a results.exo of the user's:
      exit 2, one line on stderr naming the file, no results.exo or .results.exo.partial written (the
      user's file unchanged).
"""
import argparse
import os
import resource
import re
import shutil
import subprocess
import sys

import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from tribex_runs import run  # noqa: E402

SUFFIXES = {"x", "y", "z", "xx", "yy", "zz", "xy", "yz", "zx", "xz", "yx", "zy"}


def names(nc, var):
    if var not in nc.variables:
        return []
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in nc.variables[var][:].data]


def deck_for(a):
    with open(a.deck) as f:
        text = f.read()
    text = re.sub(r"(begin results output[^\n]*\n)", r"\1        format = exodus\n", text, count=1)
    if a.termination:
        text = re.sub(r"termination time = [^\n#]*", f"termination time = {a.termination}", text, count=1)
    if a.increment:
        text = re.sub(r"(begin results output.*?)time increment = [^\n#]*", rf"\g<1>time increment = {a.increment}",
                      text, count=1, flags=re.S)
    if a.distributed:
        at = text.index("use finite element model")
        at = text.index("\n", at) + 1
        text = text[:at] + ("      begin decomposition\n        method = ptscotch\n        set-up = distributed\n"
                            "      end decomposition\n") + text[at:]
    os.makedirs(a.out, exist_ok=True)
    deck = os.path.join(a.out, "deck.i")
    with open(deck, "w") as f:
        f.write(text)
    return deck


def field_of(name):
    head, _, tail = name.rpartition("_")
    return head if head and tail in SUFFIXES else name


def compare_variables(serial, joined, rtol):
    """Every vals_* of the serial file against the joined one; returns the largest relative difference."""
    worst = 0.0
    for kind, var, prefix in (("nodal", "name_nod_var", "vals_nod_var"), ("element", "name_elem_var", "vals_elem_var")):
        vnames = names(serial, var)
        blocks = serial.dimensions["num_el_blk"].size if kind == "element" else 1
        values = {}
        for k, n in enumerate(vnames):
            keys = [f"{prefix}{k + 1}"] if kind == "nodal" else [f"{prefix}{k + 1}eb{b + 1}" for b in range(blocks)]
            values[n] = [(serial.variables[x][:].data, joined.variables[x][:].data) for x in keys if x in serial.variables]
        scale = {}
        for n, pairs in values.items():
            m = max((float(np.nanmax(np.abs(s))) for s, _ in pairs if s.size), default=0.0)
            scale[field_of(n)] = max(scale.get(field_of(n), 0.0), m)
        for n, pairs in values.items():
            for s, j in pairs:
                if s.shape != j.shape:
                    sys.exit(f"FAIL: {kind} variable {n}: shapes {s.shape} and {j.shape}")
                if not np.array_equal(np.isnan(s), np.isnan(j)):
                    sys.exit(f"FAIL: {kind} variable {n}: NaN where the serial file has none, or back")
                d = float(np.nanmax(np.abs(s - j))) if s.size else 0.0
                rel = d / scale[field_of(n)] if scale[field_of(n)] > 0 else d
                if rel > rtol:
                    sys.exit(f"FAIL: {kind} variable {n} differs by {rel:.3g} of its field's largest value (> {rtol})")
                worst = max(worst, rel)
    # The history columns, grouped the same way (momentum_x/_y/_z share the scale of the momentum).
    g1, g2 = serial.variables["vals_glo_var"][:].data, joined.variables["vals_glo_var"][:].data
    gnames = names(serial, "name_glo_var")
    largest = np.max(np.abs(g1), axis=0)
    group = {}
    for k, n in enumerate(gnames):
        group[field_of(n)] = max(group.get(field_of(n), 0.0), float(largest[k]))
    for k, n in enumerate(gnames):
        scale = group[field_of(n)]
        rel = float(np.max(np.abs(g1[:, k] - g2[:, k]))) / scale if scale > 0 else 0.0
        if rel > rtol:
            sys.exit(f"FAIL: global variable {n} differs by {rel:.3g} of its group's largest value (> {rtol})")
        worst = max(worst, rel)
    return worst


def compare_mesh(serial, joined):
    for dim in serial.dimensions:
        if dim not in joined.dimensions or serial.dimensions[dim].size != joined.dimensions[dim].size:
            sys.exit(f"FAIL: dimension {dim}: {serial.dimensions[dim].size} in the serial file, "
                     f"{joined.dimensions[dim].size if dim in joined.dimensions else 'none'} joined")
    for var in ("name_nod_var", "name_elem_var", "name_glo_var", "eb_names", "ns_names", "ss_names", "info_records"):
        if (var in serial.variables) != (var in joined.variables) or (
                var in serial.variables and not np.array_equal(serial.variables[var][:].data, joined.variables[var][:].data)):
            sys.exit(f"FAIL: {var} differs")
    exact = ["coordx", "coordy", "coordz", "time_whole"] + [v for v in serial.variables
                                                             if v.startswith(("connect", "node_ns"))]
    for var in exact:
        if not np.array_equal(serial.variables[var][:].data, joined.variables[var][:].data):
            sys.exit(f"FAIL: {var} differs from the serial file's")
    sides = sorted(v for v in serial.variables if v.startswith("elem_ss"))
    for var in sides:
        side = "side_ss" + var[len("elem_ss"):]
        s = sorted(zip(serial.variables[var][:].data, serial.variables[side][:].data))
        j = sorted(zip(joined.variables[var][:].data, joined.variables[side][:].data))
        if s != j:
            sys.exit(f"FAIL: side set {var[len('elem_ss'):]} holds other (element, side) pairs")
    return len(exact), len(sides)


def agree(a):
    deck = deck_for(a)
    serial_out, parallel_out = os.path.join(a.out, "serial"), os.path.join(a.out, f"np{a.ranks}")
    for d in (serial_out, parallel_out):
        shutil.rmtree(d, ignore_errors=True)
    run(a.tribex, deck, serial_out, 1)
    run(a.tribex, deck, parallel_out, a.ranks)
    with open(os.path.join(parallel_out, "log.txt")) as f:
        log = f.read()
    if a.distributed and "made on rank 0 instead" in log:
        sys.exit("FAIL: set-up = distributed fell back to the serial set-up: " +
                 next(line for line in log.splitlines() if "made on rank 0 instead" in line))
    files = sorted(n for n in os.listdir(parallel_out) if n.startswith("results.exo"))
    want = [f"results.exo.{a.ranks}.{r:0{len(str(a.ranks))}d}" for r in range(a.ranks)]
    if files != want:
        sys.exit(f"FAIL: the {a.ranks}-rank run wrote {files}, expected {want}")
    limit = None
    if a.open_files:  # the join under `ulimit -n` below the rank count: it must open the files in turn
        hard = resource.getrlimit(resource.RLIMIT_NOFILE)[1]
        limit = lambda: resource.setrlimit(resource.RLIMIT_NOFILE, (a.open_files, hard))  # noqa: E731
        print(f"tribex join under ulimit -n {a.open_files} ({a.ranks} rank files)")
    p = subprocess.run([a.tribex, "join", parallel_out], capture_output=True, text=True, preexec_fn=limit)
    if p.returncode != 0:
        sys.exit(f"FAIL: tribex join exited {p.returncode}: {p.stderr}")
    print(p.stdout.strip())
    with open(os.path.join(serial_out, "history.csv")) as f:
        header = f.readline().strip().split(",")
    with netCDF4.Dataset(os.path.join(serial_out, "results.exo")) as s, \
         netCDF4.Dataset(os.path.join(parallel_out, "results.exo")) as j:
        # Every history column by its whole name (mpi_hertz.i has 33-character ones; Exodus's default limit is 32).
        if names(s, "name_glo_var") != header:
            sys.exit(f"FAIL: the global variables are not history.csv's columns: {names(s, 'name_glo_var')} != {header}")
        exact, sides = compare_mesh(s, j)
        worst = compare_variables(s, j, a.rtol)
        steps = s.dimensions["time_step"].size
    print(f"{a.ranks} ranks{' (set-up = distributed)' if a.distributed else ''}: joined results.exo = serial: "
          f"{exact} arrays bitwise (coordinates, connectivity, node sets, times), {sides} side sets as pairs, "
          f"{steps} steps, largest variable difference {worst:.3g} of its field's largest value")
    print("PASS")


def segments(a):
    """--from-ranks N --ranks M --stop STEP: N ranks stopped after STEP and resumed on M into the same folder
    leave results.exo.N.r and results.exo.M.r; `tribex join` (no --ranks) stitches them by the manifest's run
    segments and must give the uninterrupted M-rank run's joined file: mesh arrays and times bitwise, every
    variable within RTOL of its field's largest value (the M-rank state from STEP on is the N-rank one moved by
    global numbers: round-off, as the N -> M restart tests)."""
    deck = deck_for(a)
    whole, cut = os.path.join(a.out, f"np{a.ranks}"), os.path.join(a.out, "segments")
    for d in (whole, cut):
        shutil.rmtree(d, ignore_errors=True)
    run(a.tribex, deck, whole, a.ranks)
    run(a.tribex, deck, cut, a.from_ranks, "--stop-at-step", str(a.stop), check=False)
    if not os.path.exists(os.path.join(cut, "restart.h5")):
        sys.exit(f"FAIL: the {a.from_ranks}-rank run stopped after step {a.stop} left no restart.h5")
    run(a.tribex, deck, cut, a.ranks, "--restart", os.path.join(cut, "restart.h5"))
    for n in (a.from_ranks, a.ranks):
        if not os.path.exists(os.path.join(cut, f"results.exo.{n}.0")):
            sys.exit(f"FAIL: no results.exo.{n}.0 in {cut}")
    for folder in (whole, cut):
        p = subprocess.run([a.tribex, "join", folder], capture_output=True, text=True)
        if p.returncode != 0:
            sys.exit(f"FAIL: tribex join {folder} exited {p.returncode}: {p.stderr}")
        print(p.stdout.strip())
    with netCDF4.Dataset(os.path.join(whole, "results.exo")) as w, netCDF4.Dataset(os.path.join(cut, "results.exo")) as j:
        exact, sides = compare_mesh(w, j)
        worst = compare_variables(w, j, a.rtol)
        steps = w.dimensions["time_step"].size
    print(f"{a.from_ranks} -> {a.ranks} ranks after step {a.stop}, joined by segments = the uninterrupted {a.ranks}-rank "
          f"run joined: {exact} arrays bitwise (times included), {sides} side sets as pairs, {steps} steps, largest "
          f"variable difference {worst:.3g} of its field's largest value")
    # A one-rank segment writes results.exo itself: the join must not replace it (its steps are in no rank file).
    serial = os.path.join(a.out, "serial_segment")
    shutil.rmtree(serial, ignore_errors=True)
    run(a.tribex, deck, serial, 1, "--stop-at-step", str(a.stop), check=False)
    run(a.tribex, deck, serial, a.ranks, "--restart", os.path.join(serial, "restart.h5"))
    with open(os.path.join(serial, "results.exo"), "rb") as f:
        before = f.read()
    expect_refused(a.tribex, serial, "a folder whose results.exo is the one-rank segment's", "results.exo")
    with open(os.path.join(serial, "results.exo"), "rb") as f:
        if f.read() != before:
            sys.exit("FAIL: tribex join changed the one-rank segment's results.exo")
    print("1 -> M in one folder: tribex join refused to replace the one-rank segment's results.exo (exit 2)")
    print("PASS")


def expect_refused(tribex, folder, what, must_name):
    p = subprocess.run([tribex, "join", folder], capture_output=True, text=True)
    lines = p.stderr.strip().splitlines()
    if p.returncode != 2 or len(lines) != 1 or must_name not in lines[0]:
        sys.exit(f"FAIL: join with {what}: exit {p.returncode}, stderr {p.stderr!r} (expected exit 2, one line naming {must_name})")
    for n in (".results.exo.partial",) + (() if "results.exo" in what else ("results.exo",)):  # a results.exo there stays
        if os.path.exists(os.path.join(folder, n)):
            sys.exit(f"FAIL: join with {what} left {n}")
    print(f"{what}: exit 2, {lines[0]}")


def bad(a):
    source = os.path.join(a.out, f"np{a.ranks}")
    rank1 = f"results.exo.{a.ranks}.{1:0{len(str(a.ranks))}d}"
    cases = []

    def copy(name):
        d = os.path.join(a.out, "bad_" + name)
        shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(source, d)
        if os.path.exists(os.path.join(d, "results.exo")):
            os.remove(os.path.join(d, "results.exo"))
        cases.append(d)
        return d

    d = copy("missing")
    os.remove(os.path.join(d, rank1))
    expect_refused(a.tribex, d, "a missing rank file", rank1)
    for name, cut in (("half", lambda size: size // 2), ("last_bytes", lambda size: size - 64)):
        d = copy(name)
        path = os.path.join(d, rank1)
        size = os.path.getsize(path)
        with open(path, "r+b") as f:
            f.truncate(cut(size))
        expect_refused(a.tribex, d, f"rank 1's file cut to {cut(size)} of {size} bytes", rank1)
    d = copy("user_file")
    with open(os.path.join(d, "results.exo"), "w") as f:
        f.write("the user's own file\n")
    expect_refused(a.tribex, d, "a user's results.exo", "results.exo")
    with open(os.path.join(d, "results.exo")) as f:
        if f.read() != "the user's own file\n":
            sys.exit("FAIL: join changed the user's results.exo")
    for d in cases:
        shutil.rmtree(d, ignore_errors=True)
    print("PASS")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mode", choices=["agree", "bad", "segments"])
    ap.add_argument("tribex")
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--distributed", action="store_true")
    ap.add_argument("--termination", default="")
    ap.add_argument("--increment", default="")
    ap.add_argument("--from-ranks", type=int, default=2, help="segments: the rank count of the stopped run")
    ap.add_argument("--stop", type=int, default=50, help="segments: the step the first run stops after")
    ap.add_argument("--open-files", type=int, default=0, help="run the join with this many file descriptors (ulimit -n)")
    a = ap.parse_args()
    ap_modes = {"agree": agree, "bad": bad, "segments": segments}
    ap_modes[a.mode](a)


if __name__ == "__main__":
    main()
