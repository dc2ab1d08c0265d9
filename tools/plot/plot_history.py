#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Plot columns of a tribex history.csv against time (PNG).

usage: /usr/bin/python3 tools/plot/plot_history.py HISTORY.csv OUT.png --columns a,b,c [--title T]
"""
import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import pyplot  # noqa: E402  (matplotlib, Agg: imported after the inputs are checked)
from cli_errors import guarded, read_csv_rows  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("history")
    p.add_argument("png")
    p.add_argument("--columns", required=True, help="comma-separated column names")
    p.add_argument("--title", default="")
    a = p.parse_args()
    rows = read_csv_rows(a.history, "a tribex history.csv", "give the history.csv of a run")
    plt = pyplot()
    names = a.columns.split(",")
    missing = [n for n in names if n not in rows[0]]
    if missing:
        print(f"error: {a.history}: no column {', '.join(missing)} (have: {', '.join(rows[0].keys())})", file=sys.stderr)
        return 2
    t = [float(r["time"]) for r in rows]
    scale, unit = (1e12, "ps") if t[-1] < 1e-9 else (1e9, "ns") if t[-1] < 1e-6 else (1.0, "s")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for n in names:
        ax.plot([x * scale for x in t], [float(r[n]) for r in rows], label=n.replace("_", " "))
    ax.set_xlabel(f"time ({unit})")
    ax.set_ylabel("SI units (J for energies)")
    ax.set_title(a.title, fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(guarded(main))
