#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The Python package `tribex` (tools/python/tribex, issue 56 scope 2) against the command line.

  check_package.py TRIBEX OUT

1. A study of tests/params/sweep_dmt.i over W = 0, 0.05, 0.1 J/m^2 through `tribex.study` (across the
   cores), and the same three runs through `tribex run --set W=...` by hand: the two tables (hold
   means of the adhesive, compressive and net normal force, 30-40 ps) must be equal, bit for bit.
2. Result: history columns as numpy arrays with history_columns.csv's units, summary.json's
   parameters, `at`; a field of results.h5 in SI (docs/tutorial/first_contact.i: displacement written
   in nm, read back in m, equal to the stored values times 1e-9; von_mises per element).
3. Errors: a --set of a parameter the deck lacks is TribexError with exit code 2 and the binary's
   error line; a missing binary is TribexError naming the fix.
Exit 0 when all holds; FAIL lines and exit 1 otherwise.
"""
import csv
import os
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
import numpy as np  # noqa: E402

import tribex  # noqa: E402
from history_checks import report_failures  # noqa: E402

DECK = str(pathlib.Path(__file__).resolve().parents[1] / "params" / "sweep_dmt.i")
VALUES = ["0 J/m^2", "0.05 J/m^2", "0.1 J/m^2"]


def hold_means(r):
    hold = r.history["time"] >= 30e-12 * (1 - 1e-9)
    return {c: float(np.mean(r.history[c][hold])) for c in ("adhesive_force", "compressive_force", "contact_normal_force")}


def by_hand(binary, out):
    rows = []
    for k, w in enumerate(VALUES):
        folder = os.path.join(out, f"cli_{k}")
        subprocess.run([binary, "run", DECK, "-o", folder, "--quiet", "--set", "W=" + w.replace(" ", "")], check=True)
        rows.append(hold_means(tribex.load(folder)))
    return rows


def main():
    binary, out = sys.argv[1], sys.argv[2]
    failures = []
    rows = tribex.study(DECK, os.path.join(out, "study"), "W", VALUES, measure=hold_means, binary_path=binary)
    tribex.write_table(rows, os.path.join(out, "study.csv"))
    cli = by_hand(binary, out)
    for row, ref in zip(rows, cli):
        print(f"W = {row['W']:5.3f} J/m^2: package {[row[c] for c in ref]}, command line {list(ref.values())}")
        if any(row[c] != ref[c] for c in ref):
            failures.append(f"W = {row['W']}: the package's table differs from the command line's")
    if [row["W"] for row in rows] != [0.0, 0.05, 0.1]:
        failures.append(f"summary.json parameters W: {[row['W'] for row in rows]}")

    r = tribex.load(os.path.join(out, "study", "W_1"))
    if r.units.get("adhesive_force") != "N" or r.history["adhesive_force"].dtype != np.float64:
        failures.append(f"units/arrays: {r.units.get('adhesive_force')}, {r.history['adhesive_force'].dtype}")
    with open(os.path.join(r.out, "history.csv")) as f:
        last = list(csv.DictReader(f))[-1]
    if r.at(r.history["time"][-1], "tip_top_displacement_z") != float(last["tip_top_displacement_z"]):
        failures.append("Result.at differs from history.csv's last row")

    tutorial = str(pathlib.Path(__file__).resolve().parents[2] / "docs" / "tutorial" / "first_contact.i")
    t = tribex.run(tutorial, os.path.join(out, "tutorial"), binary_path=binary)
    import h5py
    with h5py.File(os.path.join(t.out, "results.h5"), "r") as f:
        last = sorted(f["steps"].keys())[-1]
        stored = f["steps"][last]["nodal"]["displacement"]
        unit, raw = stored.attrs["units"], np.array(stored)
        cells = f["mesh"]["connectivity"].shape[0]
    u = t.field("displacement")
    if unit not in (b"nm", "nm") or not np.array_equal(u, raw * 1e-9):
        failures.append(f"field displacement: stored in {unit!r}, not read back as metres")
    if t.field("von_mises", step=8).shape != (cells,) or not np.all(t.field("von_mises", step=8) >= 0):
        failures.append("field von_mises: not one non-negative value per element")
    print(f"fields: displacement in {unit!r} read back in m (largest |u| {np.abs(u).max():.4g} m), "
          f"von_mises at step 8 up to {t.field('von_mises', step=8).max():.4g} Pa over {cells} elements")

    bad = None
    try:
        tribex.check(DECK, set={"Q": 1}, binary_path=binary)
    except tribex.TribexError as e:
        bad = e
    if bad is None or bad.exit_code != 2 or ": error" not in str(bad):
        failures.append(f"--set Q=1: expected TribexError exit 2 with the error line, got {bad!r}")
    else:
        print(f"--set Q=1: TribexError exit {bad.exit_code}: {bad}")
    try:
        tribex.binary(os.path.join(out, "no_such_binary"))
        failures.append("a missing binary was accepted")
    except tribex.TribexError as e:
        print(f"missing binary: {e}")
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(main())
