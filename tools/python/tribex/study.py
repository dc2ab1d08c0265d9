# SPDX-License-Identifier: MIT
"""Parameter studies: one deck, one parameter swept through `--set`, one table."""
import csv
import os

from .runner import run_many


def study(deck, out_root, parameter, values, measure, fixed=None, workers=None, ranks=1, binary_path=None):
    """Runs `deck` once per value of `parameter` (with the `fixed` parameters), into
    OUT_ROOT/<parameter>_<k>, across the cores; returns one row per value: {parameter: value, "out":
    folder, **measure(result)}. `values` are numbers (SI) or strings with units ("0.05 J/m^2")."""
    jobs = []
    for k, value in enumerate(values):
        params = dict(fixed or {})
        params[parameter] = value
        jobs.append({"deck": deck, "out": os.path.join(str(out_root), f"{parameter}_{k}"), "set": params,
                     "ranks": ranks})
    results = run_many(jobs, workers=workers, binary_path=binary_path)
    rows = []
    for value, result in zip(values, results):
        row = {parameter: result.summary["parameters"][parameter], "out": result.out}
        row.update(measure(result))
        rows.append(row)
    return rows


def write_table(rows, path):
    """The study's rows as CSV (a header row of the keys, in order)."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    return path
