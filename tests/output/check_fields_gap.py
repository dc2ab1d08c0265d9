#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The gap and contact_pressure result fields on two blocks held 1 nm apart with adhesion (fields_gap.i).

Runs `TRIBEX run DECK -o OUT`, then checks the first output (t = 0, nothing moved yet) of results.h5
(exit 1 on failure, one line per check):
  * `gap` equals the set separation, 1 nm, on the 16 slave nodes (upper_zmin, z = 6 nm) within
    1e-12 nm, and is NaN on every other node (the master's included: one pass);
  * `contact_pressure` on the slave nodes equals minus the adhesive traction at that gap,
    -(sigma_LJ(g + z0) - sigma_LJ(h_c)), sigma_LJ(h) = (8W/3z0)[(z0/h)^3 - (z0/h)^9] (docs/theory.md
    6.1, 6.3; W = 0.05 J/m^2, z0 = 0.5 nm, h_c = 20 z0), within 1e-12 relative: tensile, so
    negative; 0 on every other node; `contact_status` 0 (no node touches), `von_mises` 0 (no strain yet);
  * the units: `gap` in the file's length unit (the deck's `length unit = nm`), pressure in Pa;
  * results.exo (issue 56 scope 4): its first info record "tribex length unit: nm", the coordinates
    in nm (the slave face at z = 6), the variables `gap` (= 1 there, NaN elsewhere),
    `contact_pressure` and `von_mises` by those names.

usage: check_fields_gap.py TRIBEX DECK OUT
"""
import pathlib
import subprocess
import sys

import h5py
import netCDF4
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import report_failures  # noqa: E402


def main():
    tribex, deck, out = sys.argv[1:4]
    subprocess.run([tribex, "run", deck, "-o", out, "--quiet"], check=True)
    problems = []
    with h5py.File(f"{out}/results.h5", "r") as h:
        step = h["steps"][sorted(h["steps"])[0]]
        z = h["mesh/coordinates"][:, 2]
        gap, pressure = step["nodal/gap"], step["nodal/contact_pressure"]
        g, p = gap[:], pressure[:]
        slave = np.abs(z - 6.0) < 1e-9
        err = np.abs(g[slave] - 1.0).max()
        print(f"gap on the {slave.sum()} slave nodes: {g[slave].min():.15f} .. {g[slave].max():.15f} nm, "
              f"largest |gap - 1 nm| {err:.1e} nm (tolerance 1e-12)")
        if slave.sum() != 16 or not err < 1e-12:
            problems.append("gap differs from the 1 nm separation")
        if not np.all(np.isnan(g[~slave])):
            problems.append(f"{np.isfinite(g[~slave]).sum()} nodes off the slave surface have a gap (expected NaN)")
        W, z0, hc = 0.05, 0.5e-9, 10e-9
        lj = lambda h: 8 * W / (3 * z0) * ((z0 / h) ** 3 - (z0 / h) ** 9)  # noqa: E731
        expected = -(lj(1e-9 + z0) - lj(hc))
        p_err = np.abs(p[slave] / expected - 1).max()
        print(f"contact_pressure on the slave nodes: {p[slave].min():.10g} .. {p[slave].max():.10g} Pa, adhesion "
              f"expects {expected:.10g} Pa: largest relative difference {p_err:.1e} (tolerance 1e-12)")
        if not p_err < 1e-12:
            problems.append("contact_pressure differs from minus the adhesive traction")
        for name, values in (("contact_pressure off the slave nodes", p[~slave]),
                             ("contact_status", step["nodal/contact_status"][:]),
                             ("von_mises", step["element/von_mises"][:])):
            print(f"{name}: largest |value| {np.abs(values).max():.1e} (expected 0)")
            if np.abs(values).max() != 0.0:
                problems.append(f"{name} is not 0")
        units = (gap.attrs["units"].decode(), pressure.attrs["units"].decode(), h.attrs["length_unit"].decode())
        print(f"units: gap {units[0]}, contact_pressure {units[1]}, file length unit {units[2]}")
        if units != ("nm", "Pa", "nm"):
            problems.append(f"units {units}, expected ('nm', 'Pa', 'nm')")
    with netCDF4.Dataset(f"{out}/results.exo") as exo:
        text = lambda var: ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip()  # noqa: E731
                            for row in exo.variables[var][:].data]
        info, nodal, element = text("info_records"), text("name_nod_var"), text("name_elem_var")
        z = exo.variables["coordz"][:].data
        g = exo.variables[f"vals_nod_var{nodal.index('gap') + 1}"][0, :].data if "gap" in nodal else None
        top = np.abs(z - 6.0) < 1e-9
        print(f"results.exo: info {info[:1]}, nodal {nodal}, element {element}, slave nodes at z = 6 nm: {top.sum()}")
        if not info or info[0] != "tribex length unit: nm" or top.sum() != 16:
            problems.append("results.exo is not in nm or does not say so first in its info records")
        if g is None or "contact_pressure" not in nodal or "von_mises" not in element:
            problems.append("results.exo lacks gap, contact_pressure or von_mises")
        elif not (np.abs(g[top] - 1.0).max() < 1e-12 and np.all(np.isnan(g[~top]))):
            problems.append("results.exo's gap is not 1 nm on the slave nodes and NaN elsewhere")
    return report_failures(problems, verdict=True)


if __name__ == "__main__":
    sys.exit(main())
