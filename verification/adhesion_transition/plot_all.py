#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The figure of verification/README.md: every FE run of this folder over its reference curve,
load P/(pi W_c R) against approach delta/z0, one panel per mu_T (delta corrected by the frame compliance of the run's W = 0
twin, as compare.py does), and the pull-off table's rows.

  plot_all.py OUT_ROOT --plot adhesion_transition.png [RUN ...]

OUT_ROOT holds one output folder per deck (NAME and NAME_w0, as CTest writes them); RUN defaults to the
runs of RUNS in make_decks.py found there (not the speed variants). Prints the pull-off table
(FE: the most negative load on the withdrawal, as compare.py).
"""
import argparse
import math
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "tools" / "python"))
sys.path.insert(0, str(HERE))
from cli_errors import guarded  # noqa: E402
from compare import QUARTER, frame_compliance, read_reference  # noqa: E402
from history_checks import finish_axes, pyplot, read_history, save_figure  # noqa: E402
from make_decks import GAP_NM, RUNS  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("root")
    ap.add_argument("runs", nargs="*")
    ap.add_argument("--plot", required=True)
    a = ap.parse_args()
    root = pathlib.Path(a.root)
    names = a.runs or [n for n in RUNS if "speed" not in RUNS[n] and (root / n / "history.csv").exists()
                       and (root / (n + "_w0") / "history.csv").exists()]
    mus = sorted({RUNS[n]["mu"] for n in names})
    fig, axes = pyplot().subplots(1, len(mus), figsize=(5 * len(mus), 5), squeeze=False)
    print("| run | mu_T | FE pull-off / (pi W_c R) | reference | Maugis-Dugdale | DMT | JKR |")
    for ax, mu in zip(axes[0], mus):
        summary, ref = read_reference(HERE / "reference" / f"mu{mu:g}")
        z0, unit = summary["z0_m"], math.pi * summary["captured_work_J_m2"] * summary["radius_m"]
        ax.plot([x / z0 for x, _ in ref], [f / unit for _, f in ref], "-", color="k", lw=1.2,
                label="reference (tribex adhesion-curve)")
        right = -1e9
        for k, name in enumerate(n for n in names if RUNS[n]["mu"] == mu):
            c, _, _ = frame_compliance(read_history(root / (name + "_w0")), summary)
            rows = read_history(root / name)
            p = [QUARTER * r["contact_normal_force"] for r in rows]
            d = [-r["tip_top_displacement_z"] - GAP_NM * 1e-9 - c * f for r, f in zip(rows, p)]
            right = max(right, max(d) / z0 + 0.3)
            ax.plot([x / z0 for x in d], [f / unit for f in p], ".", ms=1.8, color=f"C{k}",
                    label=f"FE, element size {RUNS[name]['h']:g} nm")
            deepest = max(range(len(rows)), key=lambda i: -rows[i]["tip_top_displacement_z"])
            print(f"| {name} | {mu:g} | {min(p[deepest:]) / unit:.4f} | {summary['pull_off_load_control']['load_bar']:.4f} | "
                  f"{summary['maugis_dugdale_pull_off_bar']:.4f} | -2 | -1.5 |")
        ax.axhline(0, color="0.7", lw=0.6)
        ax.set_xlim(-4.5 if mu >= 1 else -2.5, right)
        ax.set_ylim(-2.2, 2.4)
        finish_axes(ax, "approach delta / z0 (z0 = 0.3 nm)", "load P / (pi W_c R), compressive positive",
                    f"mu_T = {mu:g} (E* = {summary['e_star_Pa'] / 1e9:.3g} GPa)")
    fig.suptitle("Paraboloid R = 27 nm on a flat, Lennard-Jones adhesion W = 0.05 J/m^2 (W_c = 0.9903 W), z0 = 0.3 nm:\n"
                 "FE (approach and withdrawal, delta corrected by the frame compliance) against the reference")
    fig.tight_layout()
    save_figure(fig, a.plot)
    return 0


if __name__ == "__main__":
    sys.exit(guarded(main))
