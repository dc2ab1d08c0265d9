#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Rigid flat punch: the stiffness K = F / delta of the rigid body `punch_body` (history columns
punch_body_reaction_z, punch_body_displacement_z at the end of the hold) against Mossakovskii's welded
punch on a half-space, K = 4 G a ln(3 - 4 nu) / (1 - 2 nu) (the frictionless Boussinesq/Sneddon punch
2 a E / (1 - nu^2) times (1 - nu) ln(3 - 4 nu) / (1 - 2 nu)).

The model is a cylinder R = H = L a with a fixed bottom; its stiffness is above the half-space's by the
compliance the cut-off far field misses. That correction is measured: the compliance C = 1/K of one
mesh at L = 10, 20, 40 is fitted with C(L) = C_inf - beta / L (Boussinesq's far-field displacement
falls as 1/r) and C_inf - C(10) is added to each L = 10 run's compliance. The L = 10 meshes (cells n
across the radius) then converge as K(n) = K_inf + c n^-p (the edge singularity of the pressure,
p ~ 1): with three meshes p is measured, with two it is taken as 1; K_inf is compared with the
half-space value.

  /usr/bin/python3 compare.py --domain OUT_n4_L10 OUT_n4_L20 OUT_n4_L40 --mesh 4:OUT_n4_L10 8:OUT_n8_L10 \
      [16:OUT_n16_L10] --tolerance 0.02 [--plot FIG.png]
"""
import argparse
import math
import os
import sys

import numpy as np

A, E, NU = 10e-9, 100e9, 0.3


def stiffness(out):
    d = np.genfromtxt(os.path.join(out, "run", "history.csv") if os.path.isdir(os.path.join(out, "run")) else
                      os.path.join(out, "history.csv"), delimiter=",", names=True)
    F, u = -d["punch_body_reaction_z"][-1], -d["punch_body_displacement_z"][-1]
    ke = d["kinetic_energy"][-1] / d["internal_energy"][-1]
    if ke > 1e-6:
        sys.exit(f"{out}: not at rest at the end (kinetic / internal energy {ke:.2e})")
    return F / u


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--domain", nargs=3, required=True, help="one mesh at L = 10, 20, 40")
    ap.add_argument("--mesh", nargs="+", required=True, help="CELLS:OUT at L = 10, two or three meshes")
    ap.add_argument("--tolerance", type=float, default=0.02)
    ap.add_argument("--plot")
    a = ap.parse_args()
    G = E / (2 * (1 + NU))
    k_frictionless = 2 * A * E / (1 - NU ** 2)
    k_welded = 4 * G * A * math.log(3 - 4 * NU) / (1 - 2 * NU)
    print(f"half-space: welded punch K = {k_welded:.6g} N/m (frictionless {k_frictionless:.6g} N/m, ratio "
          f"{k_welded / k_frictionless:.4f})")
    Ls = np.array([10.0, 20.0, 40.0])
    C = np.array([1 / stiffness(o) for o in a.domain])
    M = np.vstack([np.ones(3), -1 / Ls]).T
    (c_inf, beta), *_ = np.linalg.lstsq(M, C, rcond=None)
    residual = np.max(np.abs(M @ [c_inf, beta] - C)) / c_inf
    dC = c_inf - C[0]
    print(f"domain: K(L=10, 20, 40) = {', '.join(f'{1 / c:.6g}' for c in C)} N/m; C(L) = C_inf - beta/L fits to "
          f"{residual:.2e} of C_inf; K(L=inf) / K(L=10) = {C[0] / c_inf:.4f}")
    cells, K = [], []
    for item in a.mesh:
        n, out = item.split(":", 1)
        k10 = stiffness(out)
        k = 1 / (1 / k10 + dC)
        cells.append(int(n))
        K.append(k)
        print(f"mesh n = {n:>2}: K(L=10) = {k10:.6g} N/m, half-space K = {k:.6g} N/m ({100 * (k / k_welded - 1):+.2f} %)")
    K = np.array(K)
    if len(K) >= 3:
        p = math.log((K[-3] - K[-2]) / (K[-2] - K[-1])) / math.log(cells[-2] / cells[-3])
        how = "measured"
    else:
        p, how = 1.0, "taken as 1 (the slow variant measures it)"
    r = cells[-1] / cells[-2]
    k_inf = K[-1] + (K[-1] - K[-2]) / (r ** p - 1)
    error = k_inf / k_welded - 1
    print(f"mesh convergence: order p = {p:.2f} ({how}); extrapolated K = {k_inf:.6g} N/m, {100 * error:+.2f} % "
          f"from the welded punch (tolerance {100 * a.tolerance:.1f} %)")
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5.5, 4))
        h = 1 / np.array(cells, dtype=float)
        ax.plot(h, K / k_welded, "o-", label="tribex, half-space corrected")
        ax.plot([0], [k_inf / k_welded], "s", label=f"extrapolated (p = {p:.2f})")
        ax.axhline(1.0, color="k", lw=0.8, label="welded punch (Mossakovskii)")
        ax.axhline(k_frictionless / k_welded, color="k", ls="--", lw=0.8, label="frictionless (Boussinesq/Sneddon)")
        ax.set_xlabel("element size / punch radius")
        ax.set_ylabel("K / K_welded")
        ax.set_xlim(left=-0.01)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
        print("wrote", a.plot)
    if abs(error) > a.tolerance:
        print(f"FAIL: {100 * error:+.2f} % outside {100 * a.tolerance:.1f} %")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
