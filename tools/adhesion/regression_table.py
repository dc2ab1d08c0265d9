#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates tools/adhesion/pulloff_regression.csv, the pull-off and jumps of the Lennard-Jones
sphere-flat reference against the Tabor parameter (README.md, "Regression table"; recomputed by
tests/adhesion/regression_test.cpp). Runs `tribex adhesion-curve --tabor MU` with the defaults
(W = 0.05 J/m^2, z0 = 0.3 nm, h_c = 20 z0, Si E*) for each MU:

  /usr/bin/python3 tools/adhesion/regression_table.py build/bin/tribex [--out tools/adhesion/pulloff_regression.csv]
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

TABOR = [0.05, 0.1, 0.2, 0.3, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0]
HEAD = ("tabor[-],lambda[-],pull_off_bar[-],md_pull_off_bar[-],lj_over_md_minus_1_percent[-],"
        "pull_off_approach_over_z0[-],jump_out_bar[-],jump_out_approach_over_z0[-],"
        "jump_in_bar[-],jump_in_approach_over_z0[-]")


def row(tribex, mu, tmp):
    out = subprocess.run([tribex, "adhesion-curve", "--tabor", repr(mu), "--max-load-bar", "1", "--no-plot", "--json",
                          "-o", os.path.join(tmp, f"mu{mu}")], check=True, capture_output=True, text=True).stdout
    s = json.loads(out)
    z0 = s["z0_m"]

    def pair(m):
        return (m["load_bar"], m["approach_m"] / z0) if m else (math.nan, math.nan)
    p = s["pull_off_load_control"]
    md = s["maugis_dugdale_pull_off_bar"]
    vals = [mu, s["maugis_lambda"], p["load_bar"], md, 100 * (p["load_bar"] / md - 1), p["approach_m"] / z0,
            *pair(s["jump_out_displacement_control"]), *pair(s["jump_in_displacement_control"])]
    return ",".join("nan" if isinstance(v, float) and math.isnan(v) else f"{v:.7g}" for v in vals)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("tribex")
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "pulloff_regression.csv"))
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        rows = [row(a.tribex, mu, tmp) for mu in TABOR]
    text = ("# tribex adhesion-curve --tabor MU --max-load-bar 1 (W = 0.05 J/m^2, z0 = 0.3 nm, h_c = 20 z0, E* = 85.0 GPa);"
            " loads in pi W_c R, approaches in z0; nan = no jump (continuous)\n" + HEAD + "\n" + "\n".join(rows) + "\n")
    open(a.out, "w").write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
