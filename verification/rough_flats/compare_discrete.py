#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Rough-surface model with a discrete summit population (issue 10 acceptance, few asperities): the FE
run's load-area curve against a direct sum over the summits of di3_window_summits.csv at the
mean-plane separation read back from the run, within 1 %.

usage: compare_discrete.py HISTORY.csv [--plot OUT.png]
"""
import math
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import finish_axes, history_parser, pyplot, read_history, report_failures, rows_between, save_figure  # noqa: E402
from cli_errors import guarded  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
E_STAR, W = 84.1e9, 0.05                      # Pa, J/m^2 (rough_flats_discrete.i)
OFFSET = 10e-9                                # mean plane offset, m
MAP_AREA = 6.10351562e-13                     # summit map area, m^2
A0 = 2e-6 * 2e-6                              # the upper block's face, m^2
PRESS = (0.0, 150e-9)                         # s, press and hold
TOL = 0.01


def summits():
    rows = [l for l in open(os.path.join(HERE, "di3_window_summits.csv")) if l.strip() and not l.startswith("#")][1:]
    pairs = [tuple(float(v) for v in l.split(",")) for l in rows]
    mean = sum(h for h, _ in pairs) / len(pairs)
    return [(h - mean, r) for h, r in pairs]   # heights from their mean, as the model measures d


def direct_sum(pop, d):
    """Load (Hertz minus the DMT pull 2 pi W R, Eqs. 4.4, 4.10) and real area over the summits touching at d."""
    load = area = 0.0
    count = 0
    for z, r in pop:
        w = z - d
        if w <= 0:
            continue
        load += (4.0 / 3.0) * E_STAR * math.sqrt(r) * w ** 1.5 - 2.0 * math.pi * W * r
        area += math.pi * r * w
        count += 1
    scale = A0 / MAP_AREA
    return load * scale, area * scale, count


def main():
    a = history_parser(__doc__, "PNG: normal load against real contact area, FE and the direct sum").parse_args()
    pop = summits()
    rows = rows_between(read_history(a.history), *PRESS)
    points, worst_load, worst_area, contacts = [], 0.0, 0.0, set()
    for r in rows:
        d = OFFSET + r["upper_zmin_displacement_z"]
        load, area, count = direct_sum(pop, d)
        if count == 0:
            continue
        fe_load, fe_area = r["contact_normal_force"], r["real_contact_area"]
        worst_load = max(worst_load, abs(fe_load - load) / abs(load))
        worst_area = max(worst_area, abs(fe_area / area - 1))
        contacts.add(count)
        points.append((d, fe_load, load, fe_area, area))
    failures = []
    if not points or max(contacts) < len(pop):
        failures.append("the press did not bring every summit into contact")
    print(f"{len(points)} rows with {min(contacts)} to {max(contacts)} of {len(pop)} summits in contact: worst |load_FE / "
          f"load_sum - 1| = {100 * worst_load:.4f} %, worst |A_FE / A_sum - 1| = {100 * worst_area:.4f} % (tolerance 1 %)")
    for what, worst in (("load", worst_load), ("real area", worst_area)):
        if worst > TOL:
            failures.append(f"{what} differs from the direct summit sum by {100 * worst:.3f} % (> 1 %)")
    if a.plot:
        fig, ax = pyplot().subplots(figsize=(5.5, 4))
        ax.plot([p[4] * 1e12 for p in points], [p[2] * 1e6 for p in points], "-", label="direct sum over the summits")
        ax.plot([p[3] * 1e12 for p in points], [p[1] * 1e6 for p in points], "o", ms=3, label="FE (discrete rough-surface model)")
        finish_axes(ax, "real contact area (µm²)", "normal load (µN)")
        save_figure(fig, a.plot, announce=None)
    return report_failures(failures)


if __name__ == "__main__":
    sys.exit(guarded(main))
