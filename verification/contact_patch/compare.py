#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Contact patch test (contact_patch.i): two flat blocks, non-matching faces, uniform compression.

Checked (exit 1 on failure):
  * force transmission: contact force = load at the top = reaction at the bottom, relative 1e-6;
  * quasi-static end state: kinetic energy below 1e-6 of internal energy;
  * pressure uniformity as a REGRESSION GUARD: the element stress sigma_zz within 10 % of its mean.
NOT met: the issue's acceptance asks for uniform pressure to 1e-6. Node-to-face penalty contact
(even two-pass) does not pass the 3-D patch test with non-matching faces: the master side receives
the slave nodal forces through the master shape functions evaluated at the slave nodes, which is not
the consistent integral of a uniform traction. A segment-to-segment (mortar) integration would be
needed; this script prints the measured non-uniformity so that the gap is visible.
"""
import argparse
import csv
import sys

import h5py
import numpy as np


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("output")
    a = p.parse_args()
    rows = list(csv.DictReader(open(f"{a.output}/history.csv")))
    last = rows[-1]
    f = lambda k: float(last[k])  # noqa: E731
    P = f("contact_normal_force")
    top = -f("upper_zmax_reaction_z")
    bottom = f("lower_zmin_reaction_z")
    balance = max(abs(P - top), abs(P - bottom)) / P
    ke = f("kinetic_energy") / f("internal_energy")
    with h5py.File(f"{a.output}/results.h5", "r") as h:
        step = h["steps"][sorted(h["steps"].keys())[-1]]
        szz = step["element/stress"][:][:, 8]
    spread = (szz.max() - szz.min()) / abs(szz.mean())
    print(f"contact force {P * 1e9:.4f} nN, top load {top * 1e9:.4f} nN, bottom reaction {bottom * 1e9:.4f} nN: "
          f"balance {balance:.2e} (tolerance 1e-6)")
    print(f"kinetic/internal energy at the end {ke:.2e} (tolerance 1e-6)")
    print(f"sigma_zz: mean {szz.mean() / 1e6:.2f} MPa, min {szz.min() / 1e6:.2f}, max {szz.max() / 1e6:.2f}: "
          f"spread {spread:.2%} (regression guard 10 %; the acceptance's 1e-6 is NOT met by node-to-face contact)")
    ok = balance < 1e-6 and ke < 1e-6 and spread < 0.10
    print("PASS (force transmission; uniformity only guarded)" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
