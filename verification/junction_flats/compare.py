#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Junction model on flats (docs/theory.md 7.3; issue 4): in steady sliding the friction force equals
tau* x contact area within 1 %, the whole 10 x 10 nm face stays in contact, and the force reverses
with the sliding direction (base reaction in x changes sign).

usage: compare.py HISTORY.csv [--plot OUT.png]
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from cli_errors import guarded  # noqa: E402
from history_checks import (finish_axes, history_parser, mean, pyplot, read_history,  # noqa: E402
                            report_failures, rows_between, save_figure)

TAU_STAR = 10e6          # Pa, junction strength in the deck
AREA = 10e-9 * 10e-9     # m^2, the upper block's face
FORWARD = (40e-12, 60e-12)    # s, steady windows (sliding starts at 30 ps, reverses at 60 ps)
BACKWARD = (80e-12, 120e-12)


def main():
    ap = history_parser(__doc__, "PNG: friction force and tau* x area versus sliding distance")
    a = ap.parse_args()
    rows = read_history(a.history)
    failures = []
    for name, (lo, hi), sign in (("forward", FORWARD, -1.0), ("backward", BACKWARD, 1.0)):
        w = rows_between(rows, lo, hi)
        if not w:
            failures.append(f"{name}: no rows in {lo:g}-{hi:g} s")
            continue
        worst = max(abs(r["friction_force"] / r["tau_star_times_area"] - 1) for r in w)
        area = min(r["contact_area"] for r in w)
        base = mean(w, "lower_zmin_reaction_x")
        friction = mean(w, "friction_force")
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
        plt = pyplot()
        t = [r["time"] * 1e12 for r in rows]
        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot(t, [r["friction_force"] * 1e9 for r in rows], label="friction force (FE)")
        ax.plot(t, [r["tau_star_times_area"] * 1e9 for r in rows], "--", label="tau* x contact area")
        ax.plot(t, [r["lower_zmin_reaction_x"] * 1e9 for r in rows], ":", label="base reaction x")
        finish_axes(ax, "time (ps): press 0-20, slide +x 30-60, -x 60-120", "force (nN)")
        save_figure(fig, a.plot, announce=None)
    return report_failures(failures)


if __name__ == "__main__":
    sys.exit(guarded(main))
