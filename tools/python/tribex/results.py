# SPDX-License-Identifier: MIT
"""A run's output folder as Python objects: history.csv as numpy arrays with their units, summary.json,
and the fields of results.h5 in SI (docs: solver/output/README.md)."""
import csv
import json
import os

import numpy as np


class Result:
    """The output folder `out` of a tribex run (read lazily, each file once)."""

    def __init__(self, out):
        self.out = str(out)
        if not os.path.isfile(os.path.join(self.out, "history.csv")):
            from .runner import TribexError
            raise TribexError(f"{self.out}: no history.csv (not the output folder of a tribex run?)", 2)
        self._history = self._units = self._summary = None

    @property
    def history(self):
        """{column: numpy array} of history.csv, SI units (`units` gives each)."""
        if self._history is None:
            with open(os.path.join(self.out, "history.csv"), newline="") as f:
                rows = list(csv.reader(f))
            header, values = rows[0], np.array(rows[1:], dtype=float).reshape(-1, len(rows[0]))
            self._history = {name: values[:, k] for k, name in enumerate(header)}
        return self._history

    @property
    def units(self):
        """{column: unit} from history_columns.csv (the run's own column table)."""
        if self._units is None:
            with open(os.path.join(self.out, "history_columns.csv"), newline="") as f:
                self._units = {r["column"]: r["unit"] for r in csv.DictReader(f)}
        return self._units

    @property
    def summary(self):
        """summary.json as a dict (status, energies, warnings, parameters, units, ...)."""
        if self._summary is None:
            with open(os.path.join(self.out, "summary.json")) as f:
                self._summary = json.load(f)
        return self._summary

    def at(self, time, column):
        """The history value of `column` on the row nearest to `time` (s)."""
        t = self.history["time"]
        return float(self.history[column][int(np.argmin(np.abs(t - time)))])

    def field(self, name, step=-1):
        """Field `name` (nodal or element, `tribex run --list-fields`) at output step `step` (index into
        results.h5's steps, -1 the last), as a numpy array in SI (lengths in nm or um back to metres)."""
        import h5py  # only here: a study that reads histories needs no HDF5

        from results_h5 import si  # tools/python, beside this package

        with h5py.File(os.path.join(self.out, "results.h5"), "r") as f:
            group = f["steps"][sorted(f["steps"].keys())[step]]
            for kind in ("nodal", "element"):
                if name in group.get(kind, {}):
                    return np.asarray(si(group[kind][name]))
            have = [n for kind in ("nodal", "element") for n in group.get(kind, {})]
        from .runner import TribexError
        raise TribexError(f"{self.out}/results.h5: no field '{name}' (it has: {', '.join(have)})", 2)

    def field_times(self):
        """The times (s) of results.h5's output steps."""
        import h5py

        with h5py.File(os.path.join(self.out, "results.h5"), "r") as f:
            return np.array([float(f["steps"][s].attrs["time"]) for s in sorted(f["steps"].keys())])


def load(out):
    """The Result of an existing output folder."""
    return Result(out)
