#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Draws the PNG of a `tribex friction-test` or `tribex fit` command (run with Debian's /usr/bin/python3).

usage: plot_panels.py OUT.png TITLE PANEL.csv [PANEL.csv ...]

Each PANEL.csv is one subplot: a first comment line `# xlabel|ylabel|title`, then a CSV with
header; the first column is x, every other column a series. Series whose name starts with
`fit` are drawn as lines, the others as markers; empty cells are skipped. The PNG is written to
a temporary name and renamed, so a failed run leaves nothing half-written.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_panel(path):
    with open(path, newline="", encoding="utf-8") as f:
        labels = f.readline().lstrip("#").strip().split("|")
        rows = list(csv.reader(f))
    header, data = rows[0], rows[1:]
    cols = {h: [] for h in header}
    for row in data:
        for h, v in zip(header, row):
            cols[h].append(float(v) if v not in ("", "nan") else math.nan)
    return labels, header, cols


def has_points(panel):
    _, header, cols = panel
    x = cols[header[0]]
    return any(not (math.isnan(a) or math.isnan(b)) for name in header[1:] for a, b in zip(x, cols[name]))


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    out, title, paths = argv[1], argv[2], argv[3:]
    # A panel with no point to draw is left out (no empty axes in the figure).
    panels = [p for p in map(read_panel, paths) if has_points(p)] or [read_panel(paths[0])]
    fig, axes = plt.subplots(len(panels), 1, figsize=(7.5, 3.4 * len(panels)), squeeze=False)
    for ax, (labels, header, cols) in zip(axes[:, 0], panels):
        x = cols[header[0]]
        for name in header[1:]:
            pts = [(a, b) for a, b in zip(x, cols[name]) if not (math.isnan(a) or math.isnan(b))]
            if not pts:
                continue
            xs, ys = zip(*pts)
            if name.startswith("fit"):
                ax.plot(xs, ys, "-", lw=1.3, label=name)
            else:
                ax.plot(xs, ys, "o" if len(xs) <= 50 else ".", ms=5 if len(xs) <= 50 else 3, label=name)
        ax.set_xlabel(labels[0])
        ax.set_ylabel(labels[1] if len(labels) > 1 else "")
        if len(labels) > 2:
            ax.set_title(labels[2], fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(title, fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    tmp = out + ".tmp.png"
    fig.savefig(tmp, dpi=120)
    os.replace(tmp, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
