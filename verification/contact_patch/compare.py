#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Contact patch test (contact_patch.i): two flat blocks, non-matching faces, uniform compression.

The deck uses `enforcement = mortar` (segment-to-segment penalty, contact/mortar/): the nodal loads
of a uniform contact pressure are the consistent ones on both non-matching faces, so the FE
solution is the exact uniform uniaxial stress. Checked (exit 1 on failure):
  * force transmission: contact force = load at the top = reaction at the bottom, relative 1e-6;
  * quasi-static end state: kinetic energy below 1e-6 of internal energy;
  * uniform pressure: sigma_zz of ALL elements (both blocks) within 1e-6 of its mean (max - min over
    |mean|), and the other stress components (uniaxial state) below 1e-6 of |mean sigma_zz|;
  * the result fields (docs/theory.md 12.1): `contact_pressure` on every slave node in contact equal
    to the applied pressure P / A (A = 10 x 10 nm) within 1e-6, `von_mises` of every element equal to
    |sigma_zz| (uniaxial stress) within 1e-6, `gap` on every slave node the same penetration (spread
    below 1e-6 of its mean, negative) and NaN off the two contact faces (symmetric: both are slaves).
With `enforcement = node to face` the same deck gives a 5.7 % spread in sigma_zz (the master side
receives the slave nodal forces through its shape functions at the slave nodes, not the consistent
integral of a uniform traction); see verification/README.md.
"""
import argparse
import pathlib
import sys

import h5py
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from cli_errors import guarded, read_csv_rows  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("output")
    a = p.parse_args()
    rows = read_csv_rows(f"{a.output}/history.csv", "the contact patch run's history.csv",
                         "give the output folder of a finished run of contact_patch.i")
    last = rows[-1]
    f = lambda k: float(last[k])  # noqa: E731
    P = f("contact_normal_force")
    top = -f("upper_zmax_reaction_z")
    bottom = f("lower_zmin_reaction_z")
    balance = max(abs(P - top), abs(P - bottom)) / P
    ke = f("kinetic_energy") / f("internal_energy")
    with h5py.File(f"{a.output}/results.h5", "r") as h:
        step = h["steps"][sorted(h["steps"].keys())[-1]]
        stress = step["element/stress"][:]  # [element][9], row-major 3 x 3
        von_mises = step["element/von_mises"][:]
        pressure = step["nodal/contact_pressure"][:]
        status = step["nodal/contact_status"][:]
        gap = step["nodal/gap"][:]  # in the file's length unit (nm here)
    szz = stress[:, 8]
    spread = (szz.max() - szz.min()) / abs(szz.mean())
    off_axis = np.abs(stress[:, [0, 1, 2, 4, 5]]).max() / abs(szz.mean())
    print(f"contact force {P * 1e9:.4f} nN, top load {top * 1e9:.4f} nN, bottom reaction {bottom * 1e9:.4f} nN: "
          f"balance {balance:.2e} (tolerance 1e-6)")
    print(f"kinetic/internal energy at the end {ke:.2e} (tolerance 1e-6)")
    print(f"sigma_zz over all {len(szz)} elements (both blocks): mean {szz.mean() / 1e6:.4f} MPa, "
          f"spread (max - min)/|mean| {spread:.2e} (tolerance 1e-6)")
    print(f"largest other stress component / |mean sigma_zz| {off_axis:.2e} (tolerance 1e-6)")
    applied = P / 100e-18  # the contact force over the 10 x 10 nm faces, Pa
    slave = status > 0
    p_error = np.abs(pressure[slave] / applied - 1).max()
    vm_error = np.abs(von_mises / np.abs(szz) - 1).max()
    g = gap[np.isfinite(gap)]
    g_spread = (g.max() - g.min()) / abs(g.mean())
    # Symmetric: both faces are slave surfaces (upper_zmin 16 nodes, lower_zmax 25), all in contact;
    # every other node has no gap.
    gap_nodes_ok = slave.sum() == 41 and np.all(np.isfinite(gap) == slave)
    print(f"contact_pressure on the {slave.sum()} slave nodes in contact: {pressure[slave].mean() / 1e6:.4f} MPa, "
          f"largest |p / (P/A) - 1| {p_error:.2e} (tolerance 1e-6)")
    print(f"von_mises / |sigma_zz| - 1: largest {vm_error:.2e} over {len(von_mises)} elements (tolerance 1e-6)")
    print(f"gap on {len(g)} slave nodes: {g.mean():.6f} nm, spread {g_spread:.2e} (tolerance 1e-6); "
          f"NaN off the slave surface: {'yes' if gap_nodes_ok else 'NO'}")
    ok = (balance < 1e-6 and ke < 1e-6 and spread < 1e-6 and off_axis < 1e-6 and p_error < 1e-6 and vm_error < 1e-6
          and g_spread < 1e-6 and g.mean() < 0 and gap_nodes_ok)
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(guarded(main))
