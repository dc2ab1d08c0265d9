#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The contact pressure under the tip's apex (verification/soft_film_mass_scaling/README.md, issue 51).

The tip's apex node (where four of the tip's faces meet) starts on the film's centre node. contact_traction
is the slave surface's field (the film is the slave: the softer surface); the tip's nodes, the master's,
carry none. Checks at the last output: the film's node under the apex is in contact and carries the
largest traction of the field (within --tolerance of it), the field falls off from it symmetrically
(the four nearest film nodes within --tolerance of one another), and the coincident node with zero
traction is a tip node.

usage: compare_apex.py OUTPUT [--tolerance 0.01]
"""
import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from history_checks import report_failures  # noqa: E402
from cli_errors import guarded  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output")
    ap.add_argument("--tolerance", type=float, default=0.01)
    a = ap.parse_args()
    with h5py.File(os.path.join(a.output, "results.h5"), "r") as f:
        x = f["/mesh/coordinates"][:]
        conn, block = f["/mesh/connectivity"][:], f["/mesh/block_id"][:]
        last = sorted(f["/steps"].keys())[-1]
        traction = np.linalg.norm(f[f"/steps/{last}/nodal/contact_traction"][:], axis=1)
        status = f[f"/steps/{last}/nodal/contact_status"][:]
    at_apex = np.where(np.linalg.norm(x, axis=1) < 1e-9)[0]  # the apex and the film's centre start at the origin
    failures = []
    if len(at_apex) != 2:
        return report_failures([f"{len(at_apex)} nodes at the origin, expected the film's and the tip's"], True)
    film = [n for n in at_apex if traction[n] > 0.0]
    tip = [n for n in at_apex if traction[n] == 0.0]
    peak = traction.max()
    if len(film) != 1 or len(tip) != 1:
        return report_failures([f"tractions at the origin {traction[at_apex]}"], True)
    film, tip = film[0], tip[0]
    print(f"film node {film + 1} under the apex: {traction[film] / 1e9:.4f} GPa, status {status[film]:.0f}; "
          f"field's largest {peak / 1e9:.4f} GPa")
    if status[film] != 1.0 or traction[film] < (1 - a.tolerance) * peak:
        failures.append("the film's node under the apex is not at the field's largest traction")
    blocks_of_tip = set(block[np.any(conn == tip, axis=1)])
    blocks_of_film = set(block[np.any(conn == film, axis=1)])
    print(f"the node with no traction at the apex, {tip + 1}, is in blocks {sorted(blocks_of_tip)} "
          f"(the film's node in {sorted(blocks_of_film)})")
    if blocks_of_tip & blocks_of_film:
        failures.append("the zero-traction node at the apex shares a block with the film's node")
    top = np.where(np.abs(x[:, 2]) < 1e-9)[0]
    ring = [n for n in top if n != film and traction[n] > 0.0]
    ring = sorted(ring, key=lambda n: np.hypot(x[n, 0], x[n, 1]))[:4]
    values = traction[ring]
    print(f"the four nearest film nodes: {', '.join(f'{v / 1e9:.4f}' for v in values)} GPa")
    if values.max() - values.min() > a.tolerance * values.max() or values.max() > traction[film]:
        failures.append("the nearest film nodes are not symmetric below the apex's value")
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(guarded(main))
