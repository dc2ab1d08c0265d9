#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Plot a tribex run's history.csv against time (PNG): the standard panels, or chosen columns.

usage: /usr/bin/python3 tools/plot/plot_history.py OUT [PNG] [--columns a,b,c] [--title T]
  OUT   a run's output folder (its history.csv and history_columns.csv), or a history.csv
  PNG   the picture (default OUT/history.png beside the history.csv)
Without --columns, the standard panels, each with its unit and a legend, of the columns the run has:
  force: contact_normal_force, compressive_force, adhesive_force, contact_tangential_force,
         friction_force (nN);
  energy: kinetic_energy, internal_energy, external_work, contact_work, adhesion_energy and the
         dissipations that are not zero throughout (J, scaled to aJ/fJ/pJ/nJ by their size), with
         energy_error on a second axis;
  contact radius: contact_radius and its estimators (nm, or um / m for larger models).
A panel whose columns are all missing or zero is left out. --columns: the named columns on one axis
(SI units, from history_columns.csv). Exit 2 with one line for a missing file, no rows or an unknown
column.
"""
import argparse
import csv
import math
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import pyplot  # noqa: E402  (matplotlib, Agg: imported after the inputs are checked)
from cli_errors import fail, guarded, read_csv_rows  # noqa: E402

FORCES = ["contact_normal_force", "compressive_force", "adhesive_force", "contact_tangential_force", "friction_force"]
ENERGIES = ["kinetic_energy", "internal_energy", "hourglass_energy", "external_work", "contact_work",
            "adhesion_energy", "damping_dissipation", "viscous_dissipation", "silent_boundary_dissipation",
            "plastic_dissipation"]
RADII = ["contact_radius", "contact_radius_edge", "contact_radius_pressure_fit", "contact_radius_area",
         "contact_radius_max"]
PREFIX = [(1e-18, "a"), (1e-15, "f"), (1e-12, "p"), (1e-9, "n"), (1e-6, "u"), (1e-3, "m"), (1.0, "")]


def read(history):
    rows = read_csv_rows(history, "a tribex history.csv", "give a run's output folder or its history.csv")
    units = {}
    beside = os.path.join(os.path.dirname(history), "history_columns.csv")
    if os.path.isfile(beside):
        with open(beside, newline="") as f:
            units = {r["column"]: r["unit"] for r in csv.DictReader(f)}
    return {k: [float(r[k]) for r in rows] for k in rows[0]}, units


def scaled(values, unit):
    """(factor, label) putting the largest |value| between 1 and 1000 with an SI prefix on `unit`."""
    top = max((abs(v) for v in values if math.isfinite(v)), default=0.0)
    factor, prefix = 1.0, ""
    for f, p in PREFIX:
        if top >= f:
            factor, prefix = f, p
    return 1.0 / factor, prefix + unit


def panel(ax, t, data, names, unit, ylabel):
    shown = [n for n in names if n in data and any(v != 0.0 for v in data[n])]
    factor, label = scaled([v for n in shown for v in data[n]], unit)
    for n in shown:
        ax.plot(t, [v * factor for v in data[n]], label=n.replace("_", " "))
    ax.set_ylabel(f"{ylabel} ({label})")
    ax.legend(fontsize=8, loc="best")
    ax.grid(alpha=0.3)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("out", help="output folder of a run, or its history.csv")
    p.add_argument("png", nargs="?", help="picture (default: history.png beside history.csv)")
    p.add_argument("--columns", help="comma-separated column names on one axis instead of the standard panels")
    p.add_argument("--title", default="")
    a = p.parse_args()
    history = os.path.join(a.out, "history.csv") if os.path.isdir(a.out) else a.out
    png = a.png or os.path.join(os.path.dirname(history) or ".", "history.png")
    data, units = read(history)
    plt = pyplot()
    t_end = data["time"][-1]
    scale, t_unit = (1e12, "ps") if t_end < 1e-9 else (1e9, "ns") if t_end < 1e-6 else (1.0, "s")
    t = [x * scale for x in data["time"]]

    if a.columns:
        names = a.columns.split(",")
        missing = [n for n in names if n not in data]
        if missing:
            fail(f"{history}: no column {', '.join(missing)} (have: {', '.join(data)})")
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for n in names:
            ax.plot(t, data[n], label=f"{n.replace('_', ' ')} ({units.get(n, 'SI')})")
        ax.set_ylabel("value (SI units, see legend)")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        axes = [ax]
    else:
        wanted = [("force", FORCES, "N", "contact force"), ("energy", ENERGIES, "J", "energy"),
                  ("radius", RADII, "m", "contact radius")]
        kept = [w for w in wanted if any(n in data and any(v != 0.0 for v in data[n]) for n in w[1])]
        if not kept:
            fail(f"{history}: none of the standard columns (forces, energies, contact radius) is non-zero; "
                 "name some with --columns")
        fig, axes = plt.subplots(len(kept), 1, figsize=(7, 2.8 * len(kept)), sharex=True, squeeze=False)
        axes = [row[0] for row in axes]
        for ax, (kind, names, unit, label) in zip(axes, kept):
            panel(ax, t, data, names, unit, label)
            if kind == "energy" and "energy_error" in data:
                twin = ax.twinx()  # the balance error beside the terms it measures
                twin.plot(t, data["energy_error"], color="0.4", linestyle=":", label="energy error")
                twin.set_ylabel("energy error (1)")
                twin.legend(fontsize=8, loc="lower right")
    axes[-1].set_xlabel(f"time ({t_unit})")
    axes[0].set_title(a.title or os.path.abspath(history), fontsize=9)
    fig.tight_layout()
    try:
        fig.savefig(png, dpi=120)
    except OSError as e:
        fail(f"{png}: {e.strerror}; choose a writable path for the picture")
    print(f"{png}: {len(axes)} panel(s), {len(t)} rows of {history}")
    return 0


if __name__ == "__main__":
    sys.exit(guarded(main))
