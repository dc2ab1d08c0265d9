#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates tools/adhesion/pulloff_regression.csv, the pull-off and jumps of the Lennard-Jones
sphere-flat reference against the Tabor parameter (README.md, "Regression table"; recomputed by
tests/adhesion/regression_test.cpp). Runs `tribex adhesion-curve --tabor MU` with the defaults
(W = 0.05 J/m^2, z0 = 0.3 nm, h_c = 20 z0, Si E*) for each MU:

  /usr/bin/python3 tools/adhesion/regression_table.py build/bin/tribex [--out tools/adhesion/pulloff_regression.csv]
With --guidance it prints instead the FE guidance table of README.md (cohesive zone and element size
against mu_T).
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


def guidance(tribex, tmp):
    """Markdown rows: the cohesive zone d = r(g = z0) - a at the load-controlled pull-off in the two
    mu_T-only forms d/(E* z0^2/W) and d/sqrt(2 R z0), and for the 27 nm tip with W = 0.05 J/m^2,
    z0 = 0.3 nm the E* that gives mu_T, d and the element size d/4 (README.md, "FE guidance")."""
    print("| mu_T | d / (E* z0^2/W) | d / sqrt(2 R z0) | R = 27 nm: E* (GPa) | d (nm) | h_e <= d/4 (nm) |")
    print("| --- | --- | --- | --- | --- | --- |")
    r, w, z0 = 27e-9, 0.05, 0.3e-9
    for mu in TABOR:
        out = subprocess.run([tribex, "adhesion-curve", "--tabor", repr(mu), "--max-load-bar", "1", "--no-plot", "--json",
                              "-o", os.path.join(tmp, f"g{mu}")], check=True, capture_output=True, text=True).stdout
        s = json.loads(out)
        p = s["pull_off_load_control"]
        d = p["zone_radius_m"] - p["contact_radius_m"]
        g = d / (s["e_star_Pa"] * s["z0_m"] ** 2 / s["work_J_m2"])
        q = d / math.sqrt(2 * s["radius_m"] * s["z0_m"])
        e_star = math.sqrt(r * w * w / (mu ** 3 * z0 ** 3))
        d27 = g * e_star * z0 * z0 / w
        print(f"| {mu:g} | {g:.3g} | {q:.3g} | {e_star*1e-9:.3g} | {d27*1e9:.3g} | {d27/4*1e9:.3g} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("tribex")
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "pulloff_regression.csv"))
    ap.add_argument("--guidance", action="store_true")
    a = ap.parse_args()
    if a.guidance:
        with tempfile.TemporaryDirectory() as tmp:
            guidance(a.tribex, tmp)
        return
    with tempfile.TemporaryDirectory() as tmp:
        rows = [row(a.tribex, mu, tmp) for mu in TABOR]
    text = ("# tribex adhesion-curve --tabor MU --max-load-bar 1 (W = 0.05 J/m^2, z0 = 0.3 nm, h_c = 20 z0, E* = 85.0 GPa);"
            " loads in pi W_c R, approaches in z0; nan = no jump (continuous)\n" + HEAD + "\n" + "\n".join(rows) + "\n")
    open(a.out, "w").write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
