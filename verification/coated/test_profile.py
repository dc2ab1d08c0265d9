#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""CTest of pressure_profile.py's radius fits on the continuum's own contact (no FE run): the layered continuum's pressure
p_ref(r) of case 4 (`tribex layered --pressure`) turned into consistent nodal forces on a flat quarter grid of
0.2 nm faces (the study's fine mesh), then fitted back. The shape fit must return a_ref (it fits the same profile:
only the face quadrature stands between), and diagnose.py's consistent fit, whose bias on the continuum's forces
pressure_profile.py reports as cfit_ref, must stay within the +0.03 to +0.45 % in f that pressure_profile.py measured on the FE
meshes (README.md "Cases 4 and 5").

  /usr/bin/python3 verification/coated/test_profile.py TRIBEX
"""
import sys

import numpy as np

from pressure_profile import continuum_profiles, profile_forces, shape_fit
from diagnose import FaceIntegrals, consistent_fit

H = 0.2e-9          # face size, m
WIDTH = 6.0e-9      # quarter grid 0..6 nm in x and y (a_ref up to 4.4 nm in case 4)
SHAPE_TOL = 1e-6    # relative in a: the same profile and quadrature; golden section to 40 steps (bracket 1e-9)
CFIT_TOL_F = 0.005  # in f = (a/a_ref)^2 - 1: pressure_profile.py measured +0.0003 to +0.0045 on the FE meshes


def grid():
    n = round(WIDTH / H)
    xs = np.arange(n + 1) * H
    X = np.array([(x, y, 0.0) for y in xs for x in xs])
    idx = lambda i, j: j * (n + 1) + i  # noqa: E731
    faces = np.array([[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)] for j in range(n) for i in range(n)])
    return X, faces


def main():
    tribex = sys.argv[1]
    X, faces = grid()
    fi = FaceIntegrals(faces)
    fi.at(X)
    fails = 0
    for pt, (a_ref, _, x, q) in zip((0.05, 0.3, 2.0), continuum_profiles("case4_h0.2", tribex, [0.05, 0.3, 2.0])):
        force = profile_forces(fi, x, q, a_ref)
        a_shape = shape_fit(fi, force, x, q, a_ref)
        reach = np.sqrt((X[fi.nodes, :2] ** 2).sum(axis=1)[force > 0].max())
        d_cfit = (consistent_fit(fi, force, reach) / a_ref) ** 2 - 1
        ok = abs(a_shape / a_ref - 1) <= SHAPE_TOL and abs(d_cfit) <= CFIT_TOL_F
        fails += not ok
        print(f"P~ {pt}: a_ref {a_ref * 1e9:.4f} nm; shape fit a/a_ref - 1 = {a_shape / a_ref - 1:+.2e} (tolerance "
              f"{SHAPE_TOL:g}); consistent fit f/f_ref - 1 = {d_cfit:+.4f} (tolerance {CFIT_TOL_F}): {'PASS' if ok else 'FAIL'}")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
