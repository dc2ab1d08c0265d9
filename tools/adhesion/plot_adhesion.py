#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Plot of `tribex adhesion-curve`: the Lennard-Jones load-approach curve P/(pi W_c R) against the
normalised approach over the Maugis-Dugdale, DMT and JKR curves (docs/theory.md 6.7, 8.2-8.4), with
the pull-off and the jumps; and the contact radius against the load. Run by the tool with
/usr/bin/python3 (matplotlib):

  plot_adhesion.py DIR [--out DIR/adhesion.png]
"""
import argparse
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    rows = [r for r in csv.reader(line for line in open(path) if not line.startswith("#"))]
    head = rows[0]
    return {h.split("[")[0]: [float(r[i]) for r in rows[1:]] for i, h in enumerate(head)}


def marker(ax, m, style, text, scale):
    if m:
        ax.plot([m["approach_bar"]], [m["load_bar"]], style, ms=8, label=text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--out")
    a = ap.parse_args()
    d = read(os.path.join(a.dir, "adhesion.csv"))
    lim = read(os.path.join(a.dir, "limits.csv"))
    s = json.load(open(os.path.join(a.dir, "summary.json")))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    lam = s["maugis_lambda"]
    ax1.plot(d["approach_bar"], d["load_bar"], "k-", lw=1.8, label=f"Lennard-Jones (mu_T = {s['tabor']:.3g})")
    ax1.plot(lim["md_approach_bar"], lim["md_load_bar"], "b--", lw=1, label=f"Maugis-Dugdale (lambda = {lam:.3g})")
    ax1.plot(lim["dmt_approach_bar"], lim["dmt_load_bar"], "g:", lw=1, label="DMT")
    ax1.plot(lim["jkr_approach_bar"], lim["jkr_load_bar"], "r-.", lw=1, label="JKR")
    marker(ax1, s["pull_off_load_control"], "kv", "pull-off (load control)", 1)
    marker(ax1, s["jump_out_displacement_control"], "ms", "jump-out (displacement control)", 1)
    marker(ax1, s["jump_in_displacement_control"], "c^", "jump-in (displacement control)", 1)
    top = max(d["load_bar"])
    ax1.set_ylim(-2.3, top * 1.05)
    ax1.set_xlim(max(min(d["approach_bar"]), -3.0), max(d["approach_bar"]) * 1.05)
    ax1.axhline(0, color="0.7", lw=0.5)
    ax1.set_xlabel("approach delta (K^2/(pi^2 W_c^2 R))^(1/3)  (-)")
    ax1.set_ylabel("load P / (pi W_c R)  (-)")
    ax1.legend(fontsize=7, loc="upper left")
    ax1.set_title(f"R = {s['radius_m']*1e9:.4g} nm, E* = {s['e_star_Pa']*1e-9:.4g} GPa, W = {s['work_J_m2']:.3g} J/m^2, z0 = {s['z0_m']*1e9:.3g} nm",
                  fontsize=8)
    ax2.plot(d["load_bar"], d["a_bar"], "k-", lw=1.8, label="Lennard-Jones: g <= g_j radius (FE in contact)")
    sc = (s["radius_m"] ** 2 * 3.14159265358979 * s["captured_work_J_m2"] / (4 * s["e_star_Pa"] / 3)) ** (1 / 3)
    ax2.plot(d["load_bar"], [r / sc for r in d["bonded_radius"]], "k:", lw=1, label="Lennard-Jones: g <= 0.2 z0 radius")
    ax2.plot(d["load_bar"], [r / sc for r in d["compressive_radius"]], "k-.", lw=1, label="Lennard-Jones: g <= 0 radius (p > 0)")
    ax2.plot(lim["md_load_bar"], lim["a_bar"], "b--", lw=1, label="Maugis-Dugdale")
    ax2.plot(lim["dmt_load_bar"], lim["a_bar"], "g:", lw=1, label="DMT")
    ax2.plot(lim["jkr_load_bar"], lim["a_bar"], "r-.", lw=1, label="JKR")
    ax2.set_xlim(-2.2, top * 1.05)
    ax2.set_xlabel("load P / (pi W_c R)  (-)")
    ax2.set_ylabel("contact radius a (K/(pi W_c R^2))^(1/3)  (-)")
    ax2.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    out = a.out or os.path.join(a.dir, "adhesion.png")
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
