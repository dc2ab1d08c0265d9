#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""How far two runs' outputs are apart, for the before/after check of a refactor: bitwise, or
round-off with the size stated.

usage: compare_outputs.py DIR_A DIR_B
  DIR_A, DIR_B: output directories of `tribex run` (history.csv; results.h5 if both have it)

Prints "identical" for history.csv when every value is equal, else its four columns with the
largest difference relative to the column's largest |value| in DIR_A; then the same for every
floating-point dataset of results.h5. Exit 0 when compared (whatever the differences), 2 when a file
is missing or the two runs do not have the same columns, rows or datasets.
"""
import csv
import os
import sys


def fail(message):
    print(f"compare_outputs.py: {message}", file=sys.stderr)
    sys.exit(2)


def read_history(directory):
    path = f"{directory}/history.csv"
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except OSError as error:
        fail(f"{path}: {error.strerror}; give a tribex run's output directory")
    if not rows:
        fail(f"{path}:1: empty; the run wrote no history")
    try:
        return rows[0], [[float(x) for x in row] for row in rows[1:]]
    except ValueError:
        fail(f"{path}: a value that is not a number; is it a tribex history.csv?")


def worst_first(pairs):
    return sorted(pairs, key=lambda p: -p[0])


def compare_history(a_dir, b_dir):
    names_a, rows_a = read_history(a_dir)
    names_b, rows_b = read_history(b_dir)
    if names_a != names_b or len(rows_a) != len(rows_b):
        fail(f"{a_dir}/history.csv and {b_dir}/history.csv differ in columns or rows "
             f"({len(names_a)} x {len(rows_a)} against {len(names_b)} x {len(rows_b)}); compare runs of the same deck")
    result = []
    for j, name in enumerate(names_a):
        scale = max(abs(r[j]) for r in rows_a) if rows_a else 0.0
        diff = max((abs(ra[j] - rb[j]) for ra, rb in zip(rows_a, rows_b)), default=0.0)
        result.append((diff / scale if scale > 0 else diff, name))
    result = worst_first(result)
    if not result or result[0][0] == 0.0:
        print("history.csv: identical")
    else:
        print("history.csv: " + ", ".join(f"{n} {d:.2e}" for d, n in result[:4]))


def compare_results(a_dir, b_dir):
    pa, pb = f"{a_dir}/results.h5", f"{b_dir}/results.h5"
    if not (os.path.exists(pa) and os.path.exists(pb)):
        print("results.h5: not in both directories, not compared")
        return
    import h5py  # only when both runs wrote results.h5
    import numpy as np
    result = []
    with h5py.File(pa, "r") as fa, h5py.File(pb, "r") as fb:
        def visit(name, obj):
            if not isinstance(obj, h5py.Dataset) or obj.dtype.kind != "f":
                return
            if name not in fb or fb[name].shape != obj.shape:
                fail(f"{pb}: dataset {name} missing or of another shape; compare runs of the same deck")
            x, y = obj[()], fb[name][()]
            if x.size == 0:
                return
            scale = float(np.max(np.abs(x)))
            diff = float(np.max(np.abs(x - y)))
            result.append((diff / scale if scale > 0 else diff, name))
        fa.visititems(visit)
    result = worst_first(result)
    if not result or result[0][0] == 0.0:
        print(f"results.h5: {len(result)} floating-point datasets identical")
    else:
        print(f"results.h5: {len(result)} floating-point datasets; largest: "
              + ", ".join(f"{n} {d:.2e}" for d, n in result[:3]))


def main(argv):
    if len(argv) != 2:
        fail("usage: compare_outputs.py DIR_A DIR_B")
    compare_history(*argv)
    compare_results(*argv)


if __name__ == "__main__":
    main(sys.argv[1:])
