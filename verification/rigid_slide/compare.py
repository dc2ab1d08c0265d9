#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Force-controlled coated slide: how far the tip turns. From results.h5 (nodal displacement at every
output step) the rotation that fits the motion of a set of nodes best (least squares, small rotations:
u_i - u_mean = theta x (X_i - X_mean)) is taken for the nodes of the tip's top face (tip_top: the
tip's highest nodes) and for the tip's upper half (its nodes above mid-height); the largest |theta_y|
over the run, in degrees, is checked against --max-rotation. Also reported: the apex's slide against
the top's (history columns tip_apex_displacement_x, tip_top_displacement_x) and the contact normal
force while sliding steadily (from 200 ps to the end: the force control).

  /usr/bin/python3 compare.py OUT [--max-rotation 0.1] [--min-rotation DEG] [--normal-tolerance 0.02]
      [--plot FIG.png]

--min-rotation: the run must turn at least this much (the node-set load control of before, which rocks).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from results_h5 import si  # noqa: E402

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")


def best_rotation(X, u):
    """theta (rad, [3]) of the small rotation that fits u - mean(u) = theta x (X - mean(X)) best."""
    r = X - X.mean(axis=0)
    du = u - u.mean(axis=0)
    A = np.einsum("ij,ij->", r, r) * np.eye(3) - r.T @ r
    b = np.cross(r, du).sum(axis=0)
    return np.linalg.solve(A, b)


def rotations(out):
    import h5py

    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        X = si(f["mesh/coordinates"])
        conn = f["mesh/connectivity"][()]
        block = f["mesh/block_id"][()]
        names = f["mesh/block_id"].attrs["block_names"].decode().split("\n")
        tip = np.unique(conn[block == names.index("tip")])
        z = X[tip, 2]
        top = tip[z > z.max() - 1e-12]
        upper = tip[z > 0.5 * (z.min() + z.max())]
        rows = []
        for s in sorted(f["steps"].keys()):
            g = f["steps"][s]
            u = si(g["nodal/displacement"])
            rows.append((float(g.attrs["time"]), np.degrees(best_rotation(X[top], u[top])[1]),
                         np.degrees(best_rotation(X[upper], u[upper])[1])))
    return np.array(rows), len(top), len(upper)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--max-rotation", type=float, help="degrees")
    ap.add_argument("--min-rotation", type=float, help="degrees")
    ap.add_argument("--load", type=float, default=100e-9, help="the normal load, N")
    ap.add_argument("--normal-tolerance", type=float,
                    help="the contact normal force while sliding must be the load within this fraction")
    ap.add_argument("--plot")
    a = ap.parse_args()
    rows, n_top, n_upper = rotations(a.out)
    h = np.genfromtxt(os.path.join(a.out, "history.csv"), delimiter=",", names=True)
    t = h["time"]
    steady = (t > 200e-12) & (t < t[-1] - 19e-12)  # the slide at full speed
    normal = h["contact_normal_force"][steady].mean()
    top_x, apex_x = h["tip_top_displacement_x"][-1], h["tip_apex_displacement_x"][-1]
    top_max = np.abs(rows[:, 1]).max()
    upper_max = np.abs(rows[:, 2]).max()
    print(f"{a.out}: tip top ({n_top} nodes) turned at most {top_max:.4g} deg about y, the tip's upper half "
          f"({n_upper} nodes) {upper_max:.4g} deg")
    print(f"  final: tip top slid {1e9 * top_x:.3f} nm, apex {1e9 * apex_x:.3f} nm; contact normal force while sliding "
          f"{1e9 * normal:.2f} nN (load {1e9 * a.load:.0f} nN)")
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5.5, 3.8))
        ax.plot(rows[:, 0] * 1e12, rows[:, 1], "o-", label="tip top")
        ax.plot(rows[:, 0] * 1e12, rows[:, 2], "s-", label="tip, upper half")
        ax.set_xlabel("time (ps)")
        ax.set_ylabel("rotation about y (deg)")
        ax.set_title(os.path.basename(os.path.normpath(a.out)))
        ax.legend()
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
        print("wrote", a.plot)
    ok = True
    if a.max_rotation is not None and max(top_max, upper_max) > a.max_rotation:
        print(f"FAIL: rotation {max(top_max, upper_max):.4g} deg above {a.max_rotation} deg")
        ok = False
    if a.min_rotation is not None and top_max < a.min_rotation:
        print(f"FAIL: rotation {top_max:.4g} deg below {a.min_rotation} deg")
        ok = False
    if a.normal_tolerance is not None and abs(normal / a.load - 1) > a.normal_tolerance:
        print(f"FAIL: contact normal force {1e9 * normal:.2f} nN is not the load within {100 * a.normal_tolerance:g} %")
        ok = False
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
