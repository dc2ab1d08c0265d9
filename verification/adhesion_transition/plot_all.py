#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The figure of verification/README.md: every FE run of this folder over its reference curve,
load P/(pi W_c R) against approach delta/z0 (delta corrected by the frame compliance of the run's W = 0
twin, as compare.py does), and the pull-off table's rows.

  plot_all.py OUT_ROOT --plot adhesion_transition.png [RUN ...]

OUT_ROOT holds one output folder per deck (NAME and NAME_w0, as CTest writes them); RUN defaults to the
runs of RUNS in make_decks.py found there.
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
    names = a.runs or [n for n in RUNS if (root / n / "history.csv").exists() and (root / (n + "_w0") / "history.csv").exists()]
    fig, ax = pyplot().subplots(figsize=(8, 5.5))
    drawn = set()
    print("| run | mu_T | FE pull-off / (pi W_c R) | reference | Maugis-Dugdale | DMT | JKR |")
    for k, name in enumerate(names):
        mu = RUNS[name]["mu"]
        summary, ref = read_reference(HERE / "reference" / f"mu{mu:g}")
        z0, unit = summary["z0_m"], math.pi * summary["captured_work_J_m2"] * summary["radius_m"]
        c, _, _ = frame_compliance(read_history(root / (name + "_w0")), summary)
        rows = read_history(root / name)
        p = [QUARTER * r["contact_normal_force"] for r in rows]
        d = [-r["tip_top_displacement_z"] - GAP_NM * 1e-9 - c * f for r, f in zip(rows, p)]
        colour = f"C{k}"
        if mu not in drawn:
            ax.plot([x / z0 for x, _ in ref], [f / unit for _, f in ref], "-", color="k", lw=1.0,
                    label="reference (tribex adhesion-curve)" if not drawn else None)
            drawn.add(mu)
        ax.plot([x / z0 for x in d], [f / unit for f in p], ".", ms=1.5, color=colour,
                label=f"FE mu_T = {mu:g}, h = {RUNS[name]['h']:g} nm")
        print(f"| {name} | {mu:g} | {min(p) / unit:.4f} | {summary['pull_off_load_control']['load_bar']:.4f} | "
              f"{-summary['maugis_dugdale_pull_off_bar']:.4f} | -2 | -1.5 |")
    ax.axhline(0, color="0.7", lw=0.6)
    ax.set_ylim(-2.2, 2.3)
    finish_axes(ax, "approach delta / z0 (z0 = 0.3 nm; 0: undeformed surfaces at h = z0)",
                "load P / (pi W_c R) (compressive positive; W_c = 0.9903 W)",
                "Sphere on flat, Lennard-Jones adhesion: FE against the reference, R = 27 nm, W = 0.05 J/m^2")
    save_figure(fig, a.plot)
    return 0


if __name__ == "__main__":
    sys.exit(guarded(main))
