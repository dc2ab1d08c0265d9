#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes a copy of a restart file with one dataset of group rank_0 replaced (tests/bounds/cases.sh).

usage: edit_restart.py SRC DST NAME real|int|huge VALUE
  real VALUE: a float64 scalar;  int VALUE: an int64 scalar, or `same` for the old values as int64;
  huge: a float64 dataset stating 2^40 values with no storage (a size the file cannot hold).
"""
import shutil
import sys

import h5py
import numpy as np

src, dst, name, kind, value = sys.argv[1:6]
shutil.copy(src, dst)
with h5py.File(dst, "r+") as f:
    group = f["rank_0"]
    old = group[name][...]
    del group[name]
    if kind == "huge":
        group.create_dataset(name, shape=(2**40,), dtype="f8")
    elif kind == "int":
        group.create_dataset(name, data=np.asarray(old if value == "same" else [int(value)]).astype(np.int64))
    else:
        group.create_dataset(name, data=np.array([float(value)]))
