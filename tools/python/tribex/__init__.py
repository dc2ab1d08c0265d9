# SPDX-License-Identifier: MIT
"""tribex from Python (issue 56 scope 2): check and run decks, parameter studies, results as numpy arrays.

    import tribex
    r = tribex.run("docs/tutorial/first_contact.i", "out", set={"W": "0.1 J/m^2"})
    r.history["friction_force"]          # numpy array, N (r.units["friction_force"] == "N")
    r.summary["energy_error"]
    r.field("von_mises", step=-1)        # numpy array in SI, from results.h5
    table = tribex.study("docs/tutorial/first_contact.i", "sweep", "W", ["0.02 J/m^2", "0.05 J/m^2"],
                         measure=lambda r: {"adhesive_force": r.at(85e-12, "adhesive_force")})

The package drives the `tribex` binary (the repository's build/bin/tribex, found from this file, or
$TRIBEX, or `binary=`); it holds no physics of its own. Import it with tools/python on the path:
`./tribex.sh python SCRIPT.py` sets it, or PYTHONPATH=REPO/tools/python (tools/python/README.md).
Uses numpy; h5py only for `Result.field`. Errors: `TribexError` with the binary's one-line message
and its exit code (2 bad input, 3 numerical failure, 130 stopped).
"""
from .results import Result, load
from .runner import TribexError, binary, check, run, run_many
from .study import study, write_table

__all__ = ["Result", "TribexError", "binary", "check", "load", "run", "run_many", "study", "write_table"]
