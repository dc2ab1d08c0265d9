#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes a copy of a restart file with rank 0's array NAME replaced (tests/bounds/cases.sh).

usage: edit_restart.py SRC DST NAME real|int|huge VALUE
  real VALUE: a float64 scalar;  int VALUE: an int64 scalar, or `same` for the old values as int64;
  huge: a float64 dataset stating 2^40 values with no storage (a size the file cannot hold).
Format version 1 (solver/restart/restart_file.cpp): dataset NAME of group rank_0 replaced. Version 2: the
dataset reals/NAME or integers/NAME (every rank's array in rank order) rewritten with rank 0's part
replaced and its count (real_counts/NAME, integer_counts/NAME) set to match, the dataset staying where it
was (the reader takes the type from the dataset: an int64 reals/u is the edited file of version 1's int64 u).
"""
import shutil
import sys

import h5py
import numpy as np

src, dst, name, kind, value = sys.argv[1:6]
shutil.copy(src, dst)


def replacement(old):
    if kind == "int":
        return np.asarray(old if value == "same" else [int(value)]).astype(np.int64)
    return np.array([float(value)])


with h5py.File(dst, "r+") as f:
    if f.attrs["format_version"] == 1:
        group = f["rank_0"]
        old = group[name][...]
        del group[name]
        if kind == "huge":
            group.create_dataset(name, shape=(2**40,), dtype="f8")
        else:
            group.create_dataset(name, data=replacement(old))
    else:
        values, counts = ("reals", "real_counts") if name in f["reals"] else ("integers", "integer_counts")
        c = f[counts][name][...]
        everything = f[values][name][...]
        mine, rest = everything[:max(c[0], 0)], everything[max(c[0], 0):]
        del f[values][name]
        if kind == "huge":
            f[values].create_dataset(name, shape=(2**40,), dtype="f8")
            c[0] = 2**40 - len(rest)
        else:
            new = replacement(mine)
            f[values].create_dataset(name, data=np.concatenate([new, rest.astype(new.dtype)]))
            c[0] = len(new)
        f[counts][name][...] = c
