# SPDX-License-Identifier: MIT
"""Pieces shared by the compare scripts that read a run's history.csv: reading it, selecting rows by
a window, means, relative errors, a deck's piecewise-linear function, the trapezoid rule, the
quasi-static (kinetic / internal energy) figure, the command line, the plot set-up and the failure report. Each script keeps its own reference, tolerances and messages.
"""
import argparse
import os

from cli_errors import InputError, read_csv_rows, require_file


def read_history(path):
    """The rows of a tribex history.csv as dicts of floats (column name -> value, SI). `path` is the
    file (a name ending in .csv) or the run's output folder."""
    if os.path.isdir(path) or not path.endswith(".csv"):
        path = os.path.join(path, "history.csv")
    rows = read_csv_rows(path, "a tribex history.csv", "give the history.csv (or output folder) of a finished run")
    try:
        return [{k: float(v) for k, v in r.items()} for r in rows]
    except (TypeError, ValueError) as e:  # a cut row (None) or a word where a number belongs
        raise InputError(f"{path}: not a complete tribex history.csv ({e})") from None


# History columns whose values add up over the nodes (units as history_columns.csv writes them): on a
# quarter model they are a quarter of the full problem's.
EXTENSIVE_UNITS = ("N", "m^2", "J", "W", "kg m/s")


def output_folder(path):
    """The output folder of `path` (a history.csv or the folder itself)."""
    return path if os.path.isdir(path) or not path.endswith(".csv") else os.path.dirname(path) or "."


def model_fraction(path):
    """The part of the full problem a run models: 0.25 for a generated asperity with `symmetry =
    quarter` (mesh/asperity.hpp: x, y >= 0 only), else 1. Read from the resolved deck in the run's
    log.txt (every key written, defaults included), so a compare script needs no option for it."""
    log = os.path.join(output_folder(path), "log.txt")
    require_file(log, "the run's log.txt (its resolved deck says whether the model is a quarter)",
                 "give the output folder of a finished run")
    inside = False
    with open(log) as f:
        for line in f:
            words = line.split()
            if words[:3] == ["begin", "generated", "asperity"]:
                inside = True
            elif words[:3] == ["end", "generated", "asperity"]:
                inside = False
            elif inside and words == ["symmetry", "=", "quarter"]:
                return 0.25
    return 1.0


def read_full_history(path):
    """read_history(path) as the full problem's: on a quarter model (model_fraction) the forces, areas,
    energies, powers and momenta (EXTENSIVE_UNITS, from history_columns.csv) times 4 and
    contact_radius_area, sqrt(area/pi), times 2. Lengths, displacements, the other contact radii (they
    are distances from the axis) and energy_error (a ratio) are the same as the full model's. A lateral
    component (x, y) of a quarter's force is its own, not a quarter of the full's (zero by symmetry)."""
    rows = read_history(path)
    fraction = model_fraction(path)
    if fraction == 1.0:
        return rows
    units = os.path.join(output_folder(path), "history_columns.csv")
    scaled = [r["column"] for r in read_csv_rows(units, "the run's history_columns.csv") if r["unit"] in EXTENSIVE_UNITS]
    for row in rows:
        for name in scaled:
            if name in row:
                row[name] /= fraction
        if "contact_radius_area" in row:
            row["contact_radius_area"] /= fraction ** 0.5
    return rows


def history_parser(doc, plot_help, positional="history"):
    """The command line every compare script starts from: the run's history (or output folder) as
    `positional`, and --plot PNG with `plot_help`; the script adds its own options."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument(positional)
    ap.add_argument("--plot", help=plot_help)
    return ap


def rows_between(rows, lo, hi, key="time"):
    """The rows with lo <= row[key] <= hi."""
    return [r for r in rows if lo <= r[key] <= hi]


def deepest_index(rows, key="tip_top_displacement_z"):
    """Index of the row where the tip top is deepest (most negative key): the end of the loading
    branch of an indentation (rows[: i + 1]) and the start of the withdrawal (rows[i:])."""
    z = [r[key] for r in rows]
    return min(range(len(z)), key=lambda i: z[i])


def mean(rows, key):
    """Mean of row[key] over rows."""
    return sum(r[key] for r in rows) / len(rows)


def relative_errors(measured, reference):
    """|m - r| / r for each pair (r > 0)."""
    return [abs(m - r) / r for m, r in zip(measured, reference)]


def radius_errors(rows, column, reference):
    """For the rows a check uses: the loads P (contact_normal_force), the FE radius in `column`, the
    reference radius `reference(P)` and the relative errors (verification/hertz and dmt compare.py)."""
    loads = [r["contact_normal_force"] for r in rows]
    measured = [r[column] for r in rows]
    expected = [reference(x) for x in loads]
    return loads, measured, expected, relative_errors(measured, expected)


def max_and_mean(errors):
    """(largest, mean) of a list of errors."""
    return max(errors), sum(errors) / len(errors)


def max_kinetic_over_stored(rows, stored=("internal_energy",), default=None):
    """Largest kinetic energy / stored energy over rows, the quasi-static check (CONVENTIONS: KE a small
    fraction of IE); stored = the history columns summed as the stored energy (a zero sum counts as
    1e-300 J). `default` when rows is empty."""
    ratios = [r["kinetic_energy"] / max(sum(r[k] for k in stored), 1e-300) for r in rows]
    return max(ratios) if ratios else default


def piecewise_linear(points, x):
    """The piecewise-linear function through `points` ((x, y) pairs, x increasing) at x, held
    constant beyond the last point: a deck's `type = piecewise linear` function."""
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return points[-1][1]


def trapezoid(xs, ys):
    """The integral of ys over xs by the trapezoid rule."""
    return sum(0.5 * (ys[i] + ys[i + 1]) * (xs[i + 1] - xs[i]) for i in range(len(xs) - 1))


def pyplot():
    """matplotlib.pyplot on the Agg backend (no display: CTest, CI)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def finish_axes(ax, xlabel, ylabel, title=None):
    """Axis labels (with units), an optional title and the legend, as every compare plot has them."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)
    ax.legend(fontsize=8)


def save_figure(fig, path, announce="plot: "):
    """tight_layout, then the PNG at 120 dpi; prints `announce` + path unless announce is None."""
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    if announce is not None:
        print(f"{announce}{path}")


def report_failures(failures, verdict=False, ok=None):
    """Prints one `FAIL: ...` line per failure (then PASS or FAIL when `verdict`; the line `ok` when
    nothing failed); returns the exit status, 1 if anything failed."""
    for line in failures:
        print("FAIL:", line)
    if ok and not failures:
        print(ok)
    if verdict:
        print("PASS" if not failures else "FAIL")
    return 1 if failures else 0
