#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Diagnostic (not a check): the contact radius of an asperity run (verification/hertz/*.i) from the
slave nodal forces through consistent loads, at every field output of results.h5.

Hertz's pressure p(r) = p0 sqrt(1 - r^2/a^2) acting on the tip surface gives the tip node I the force
f_I = p0 g_I(a), g_I(a) = int sqrt(1 - r^2/a^2)_+ N_I dA over the tip-surface faces (bilinear N_I,
deformed x and y, 10 x 10 Gauss points per face). For each output the script fits p0 (linear least
squares) and a (golden-section search on the residual) to the nodal forces of all tip-surface nodes
within 12 nm of the axis, those outside the contact (zero force) included: nodes just outside the
contact carry force through N_I, and the ones beyond carry none, so both bound a. The nodal forces are
the contact_traction field times each node's area int N_I dA (the code's traction is force over
tributary area). Printed against a_H(P) with P the history's contact_normal_force at that time, beside
the history's contact_radius_pressure_fit. On a quarter model (symmetry = quarter) the faces and forces
are the quarter's, which the fit of a and p0 takes as they are, and P the full problem's (times 4).
verification/hertz/README.md quotes its output.

    /usr/bin/python3 verification/hertz/consistent_fit.py OUT
"""
import argparse
import math
import pathlib
import sys

import h5py
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from contact_theory import dmt_radius, effective_modulus  # noqa: E402
from history_checks import read_full_history  # noqa: E402
from results_h5 import si  # noqa: E402

E, NU, R = 161e9, 0.23, 27e-9
ESTAR = effective_modulus(E, NU)
GAUSS_POINTS = 10   # per direction and face: the sqrt edge inside a face needs more than a few
AXIS_RANGE = 12e-9  # tip-surface faces with their centre this close to the axis take part


def tip_surface_faces(f):
    """Bottom faces of block `tip` (nodes 0-3 of each hex, the generator's z-min face) that no other
    tip element covers with its top face: the tip surface."""
    block_id = f["mesh/block_id"][:]
    names = f["mesh/block_id"].attrs["block_names"]
    names = (names.decode() if isinstance(names, bytes) else str(names)).split("\n")
    tip = f["mesh/connectivity"][:][block_id == names.index("tip")]
    tops = {tuple(sorted(q)) for q in tip[:, 4:]}
    return np.array([q for q in tip[:, :4] if tuple(sorted(q)) not in tops])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output", help="the run's output folder (results.h5 with displacement and contact_traction)")
    a = ap.parse_args()
    rows = read_full_history(a.output)  # P of the full problem (a quarter model's times 4)
    with h5py.File(pathlib.Path(a.output) / "results.h5", "r") as f:
        X = si(f["mesh/coordinates"])  # m, whatever the file's length unit
        faces = tip_surface_faces(f)
        centres = X[faces].mean(axis=1)
        faces = faces[np.hypot(centres[:, 0], centres[:, 1]) < AXIS_RANGE]
        nodes, local = np.unique(faces, return_inverse=True)
        local = local.reshape(faces.shape)
        g, w = np.polynomial.legendre.leggauss(GAUSS_POINTS)
        xi, eta = (v.ravel() for v in np.meshgrid(g, g))
        weight = np.outer(w, w).ravel()
        N = 0.25 * np.array([(1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta)])
        dN_dxi = 0.25 * np.array([-(1 - eta), 1 - eta, 1 + eta, -(1 + eta)])
        dN_deta = 0.25 * np.array([-(1 - xi), -(1 + xi), 1 + xi, 1 - xi])

        def nodal_integral(values):  # values [face][point] -> sum over faces of int values N_I dA
            out = np.zeros(len(nodes))
            for k in range(4):
                np.add.at(out, local[:, k], (N[k][None, :] * values).sum(axis=1))
            return out

        print("  t (ps)    P (nN)  a_H (nm)  pressure fit  consistent fit  nodes in contact")
        for key in sorted(f["steps"].keys()):
            step = f["steps"][key]
            t = float(step.attrs["time"])
            x = X + si(step["nodal/displacement"])
            xy = x[faces][:, :, :2]
            jac = np.abs(np.einsum("aq,fa->fq", dN_dxi, xy[:, :, 0]) * np.einsum("aq,fa->fq", dN_deta, xy[:, :, 1])
                         - np.einsum("aq,fa->fq", dN_dxi, xy[:, :, 1]) * np.einsum("aq,fa->fq", dN_deta, xy[:, :, 0]))
            dA = jac * weight[None, :]
            rho2 = np.einsum("aq,fa->fq", N, xy[:, :, 0]) ** 2 + np.einsum("aq,fa->fq", N, xy[:, :, 1]) ** 2
            force = np.maximum(step["nodal/contact_traction"][:][nodes, 2] * nodal_integral(dA), 0.0)
            if np.count_nonzero(force) < 5:
                continue

            def residual(radius):
                shape = nodal_integral(np.sqrt(np.clip(1 - rho2 / radius**2, 0, None)) * dA)
                p0 = shape @ force / (shape @ shape)
                return ((force - p0 * shape) ** 2).sum()

            reach = math.sqrt(((x[nodes, :2] ** 2).sum(axis=1))[force > 0].max())
            lo, hi = 0.5 * reach, 1.5 * reach
            for _ in range(60):  # golden section
                m1, m2 = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
                lo, hi = (lo, m2) if residual(m1) < residual(m2) else (m1, hi)
            row = min(rows, key=lambda r: abs(r["time"] - t))
            P = row["contact_normal_force"]
            a_h = dmt_radius(P, R, 0.0, ESTAR)
            print(f"{t * 1e12:8.1f} {P * 1e9:9.1f} {a_h * 1e9:9.3f} {row['contact_radius_pressure_fit'] / a_h - 1:+12.2%}"
                  f" {0.5 * (lo + hi) / a_h - 1:+15.2%} {np.count_nonzero(force):10d}")


if __name__ == "__main__":
    main()
