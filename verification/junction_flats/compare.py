#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Junction model on flats (physics.md 7.3; issue 4): in steady sliding the friction force equals
tau* x contact area within 1 %, the whole 10 x 10 nm face stays in contact, and the force reverses
with the sliding direction (base reaction in x changes sign).

usage: compare.py HISTORY.csv [--plot OUT.png]
"""
import argparse
import csv
import sys

TAU_STAR = 10e6          # Pa, junction strength in the deck
AREA = 10e-9 * 10e-9     # m^2, the upper block's face
FORWARD = (40e-12, 60e-12)    # s, steady windows (sliding starts at 30 ps, reverses at 60 ps)
BACKWARD = (80e-12, 120e-12)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("history")
    ap.add_argument("--plot", help="PNG: friction force and tau* x area versus sliding distance")
    a = ap.parse_args()
    with open(a.history) as f:
        rows = list(csv.DictReader(f))
    failures = []

    def window(lo, hi):
        return [r for r in rows if lo <= float(r["time"]) <= hi]

    for name, (lo, hi), sign in (("forward", FORWARD, -1.0), ("backward", BACKWARD, 1.0)):
        w = window(lo, hi)
        if not w:
            failures.append(f"{name}: no rows in {lo:g}-{hi:g} s")
            continue
        worst = max(abs(float(r["friction_force"]) / float(r["tau_star_times_area"]) - 1) for r in w)
        area = min(float(r["contact_area"]) for r in w)
        base = sum(float(r["lower_zmin_reaction_x"]) for r in w) / len(w)
        friction = sum(float(r["friction_force"]) for r in w) / len(w)
        print(f"{name}: friction {friction:.5g} N vs tau* A {TAU_STAR * AREA:.5g} N; worst |F/(tau* A_real) - 1| "
              f"{100 * worst:.3f} %; min contact area {area:.5g} m^2; mean base reaction x {base:.4g} N")
        if worst > 0.01:
            failures.append(f"{name}: friction differs from tau* x contact area by {100 * worst:.2f} % (> 1 %)")
        if abs(friction / (TAU_STAR * AREA) - 1) > 0.01:
            failures.append(f"{name}: friction {friction:.4g} N differs from tau* x 100 nm^2 by more than 1 %")
        if abs(area / AREA - 1) > 1e-6:
            failures.append(f"{name}: contact area {area:.4g} m^2, expected the full face {AREA:.4g} m^2")
        if not sign * base > 0.5 * TAU_STAR * AREA:
            failures.append(f"{name}: base reaction x {base:.4g} N does not oppose the friction on the lower block")

    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        t = [float(r["time"]) * 1e12 for r in rows]
        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot(t, [float(r["friction_force"]) * 1e9 for r in rows], label="friction force (FE)")
        ax.plot(t, [float(r["tau_star_times_area"]) * 1e9 for r in rows], "--", label="tau* x contact area")
        ax.plot(t, [float(r["lower_zmin_reaction_x"]) * 1e9 for r in rows], ":", label="base reaction x")
        ax.set_xlabel("time (ps): press 0-20, slide +x 30-60, -x 60-120")
        ax.set_ylabel("force (nN)")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
