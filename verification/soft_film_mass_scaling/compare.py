#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A soft-film press-slide-withdraw run against its twin (verification/soft_film_mass_scaling/README.md).

Checks on the run: the run ended normally; |energy_error| <= --energy-tolerance on every row; the contact
force in the hold (520-550 ps) steady: (max - min) / mean <= --hold-tolerance. Against the twin (the same
deck without mass scaling, --reference): the hold's mean contact force, and with friction the mean of
friction / (N + F_adh) over the fast part of the slide (240-400 ps), each within --twin-tolerance.
Prints the figures and PASS, or FAIL with each failure; exit 1 on FAIL.

usage: compare.py OUTPUT [--reference TWIN_OUTPUT] [--plot PNG]
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from cli_errors import guarded  # noqa: E402
from history_checks import (finish_axes, history_parser, mean, pyplot, read_history, report_failures,  # noqa: E402
                            rows_between, save_figure)

HOLD = (520e-12, 550e-12)   # s: the hold after the slide, before the withdrawal
SLIDE = (240e-12, 400e-12)  # s: the fast part of the slide (0.45-2.55 nm of the 3 nm)


def figures(out):
    """The run's checked figures: largest |energy_error|, hold force (mean, spread), friction ratio."""
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    rows = read_history(out)
    hold = rows_between(rows, *HOLD)
    slide = rows_between(rows, *SLIDE)
    force = [r["contact_normal_force"] for r in hold]
    fig = {"exit_code": summary.get("exit_code"), "rows": rows,
           "energy": max(abs(r["energy_error"]) for r in rows),
           "hold_mean": sum(force) / len(force) if force else float("nan"),
           "hold_spread": (max(force) - min(force)) / (sum(force) / len(force)) if force else float("nan"),
           "friction_ratio": None}
    if slide and mean(slide, "friction_force") > 0.0:
        fig["friction_ratio"] = sum(r["friction_force"] / (r["contact_normal_force"] + r["adhesive_force"])
                                    for r in slide) / len(slide)
    return fig


def plot(path, run, twin):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    for label, f in (("this run", run), ("twin (no mass scaling)", twin)):
        if f:
            ax.plot([r["time"] * 1e12 for r in f["rows"]], [r["contact_normal_force"] * 1e9 for r in f["rows"]],
                    label=label)
    finish_axes(ax, "time (ps)", "contact normal force (nN)", "soft film: press, hold, slide, hold, withdraw")
    save_figure(fig, path)


def main():
    ap = history_parser(__doc__, "PNG of the contact force over time, with the twin's", positional="output")
    ap.add_argument("--reference", help="the twin's output folder (the same deck without mass scaling)")
    ap.add_argument("--energy-tolerance", type=float, default=0.005, help="largest |energy_error| (default 0.005)")
    ap.add_argument("--hold-tolerance", type=float, default=0.01, help="largest hold spread / mean (default 0.01)")
    ap.add_argument("--twin-tolerance", type=float, default=0.01, help="largest relative difference to the twin")
    a = ap.parse_args()
    run = figures(a.output)
    twin = figures(a.reference) if a.reference else None
    failures = []
    if run["exit_code"] != 0:
        failures.append(f"the run ended with exit code {run['exit_code']}")
    print(f"max |energy_error| {100 * run['energy']:.4f} % (tolerance {100 * a.energy_tolerance:g} %)")
    if not run["energy"] <= a.energy_tolerance:
        failures.append(f"|energy_error| {100 * run['energy']:.4f} % > {100 * a.energy_tolerance:g} %")
    print(f"hold 520-550 ps: contact force mean {run['hold_mean'] * 1e9:.3f} nN, spread "
          f"{100 * run['hold_spread']:.3f} % of it (tolerance {100 * a.hold_tolerance:g} %)")
    if not run["hold_spread"] <= a.hold_tolerance:
        failures.append(f"hold spread {100 * run['hold_spread']:.3f} % > {100 * a.hold_tolerance:g} %")
    if run["friction_ratio"] is not None:
        print(f"slide 240-400 ps: friction / (N + F_adh) {run['friction_ratio']:.5f}")
    if twin:
        pairs = [("hold contact force", run["hold_mean"], twin["hold_mean"])]
        if run["friction_ratio"] is not None or twin["friction_ratio"] is not None:
            pairs.append(("friction / (N + F_adh)", run["friction_ratio"] or float("nan"),
                          twin["friction_ratio"] or float("nan")))
        for what, value, ref in pairs:
            diff = value / ref - 1.0
            print(f"against the twin: {what} {value:.6g} vs {ref:.6g} ({100 * diff:+.3f} %, tolerance "
                  f"{100 * a.twin_tolerance:g} %)")
            if not abs(diff) <= a.twin_tolerance:
                failures.append(f"{what} {100 * diff:+.3f} % from the twin")
    if a.plot:
        plot(a.plot, run, twin)
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(guarded(main))
