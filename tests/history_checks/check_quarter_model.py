#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""history_checks.model_fraction / read_full_history (tools/python/history_checks.py) on made-up run
folders: a log.txt whose resolved deck has `symmetry = quarter` inside `begin generated asperity` is a
quarter model, and its forces (N), areas (m^2), energies (J), powers (W) and momenta come back times 4,
contact_radius_area times 2, lengths and ratios unchanged; `symmetry = quarter` outside that block, or
`symmetry = none`, is the full model (unchanged); a folder without log.txt is bad input (exit 2 in a
script). Usage: check_quarter_model.py WORK_FOLDER"""
import os
import pathlib
import shutil
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from cli_errors import InputError  # noqa: E402
from history_checks import model_fraction, read_full_history, report_failures  # noqa: E402

COLUMNS = [("time", "s"), ("contact_normal_force", "N"), ("contact_area", "m^2"), ("internal_energy", "J"),
           ("friction_power", "W"), ("momentum_z", "kg m/s"), ("energy_error", "-"), ("contact_radius", "m"),
           ("contact_radius_area", "m"), ("contact_nodes", "count"), ("apparent_pressure", "Pa")]
ROW = [1e-12, 2e-7, 3e-17, 4e-18, 5e-6, 6e-20, 1e-5, 7e-9, 8e-9, 9, 1e8]
LOG = """begin sierra x
  begin finite element model asperity
    begin generated asperity
      radius = 2.7e-08
      symmetry = {inside}
    end generated asperity
  end finite element model asperity
  begin presto procedure p
    symmetry = {outside}
  end presto procedure p
end sierra x
"""


def run_folder(root, name, inside, outside, log=True):
    folder = os.path.join(root, name)
    os.makedirs(folder)
    with open(os.path.join(folder, "history_columns.csv"), "w") as f:
        f.write("column,unit,definition\n" + "".join(f"{c},{u},made up\n" for c, u in COLUMNS))
    with open(os.path.join(folder, "history.csv"), "w") as f:
        f.write(",".join(c for c, _ in COLUMNS) + "\n" + ",".join(repr(v) for v in ROW) + "\n")
    if log:
        with open(os.path.join(folder, "log.txt"), "w") as f:
            f.write(LOG.format(inside=inside, outside=outside))
    return folder


def main():
    root = sys.argv[1]
    shutil.rmtree(root, ignore_errors=True)
    failures = []
    quarter = run_folder(root, "quarter", "quarter", "none")
    expected = dict(zip((c for c, _ in COLUMNS), ROW))
    for name in ("contact_normal_force", "contact_area", "internal_energy", "friction_power", "momentum_z"):
        expected[name] *= 4
    expected["contact_radius_area"] *= 2
    if model_fraction(quarter) != 0.25 or model_fraction(os.path.join(quarter, "history.csv")) != 0.25:
        failures.append(f"quarter: model_fraction {model_fraction(quarter)}, expected 0.25")
    got = read_full_history(os.path.join(quarter, "history.csv"))[0]
    for name, value in expected.items():
        if abs(got[name] - value) > 1e-15 * abs(value):
            failures.append(f"quarter: {name} {got[name]!r}, expected {value!r}")
    for name, inside, outside in (("full", "none", "none"), ("outside", "none", "quarter")):
        folder = run_folder(root, name, inside, outside)
        got = read_full_history(folder)[0]
        if model_fraction(folder) != 1.0 or [got[c] for c, _ in COLUMNS] != ROW:
            failures.append(f"{name}: model_fraction {model_fraction(folder)} and the row {got} (expected 1 and unchanged)")
    try:
        read_full_history(run_folder(root, "no_log", "none", "none", log=False))
        failures.append("no_log: read without log.txt (expected InputError)")
    except InputError as e:
        print(f"no log.txt: {e}")
    print("quarter: forces, areas, energies, powers, momenta x4, contact_radius_area x2, the rest unchanged")
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(main())
