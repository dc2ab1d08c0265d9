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

With --pressure-tolerance, also the pressure under the punch (the result field rigid_body_force at the
end: the force the punch puts into the body at each of its nodes, over the node's tributary area), ring by
ring away from the singular edge (r < 0.8 a), against the welded punch's pressure on a half-space for the
run's own total force P (welded_punch.py: a ring boundary-element solution, converged to 1e-5; README.md
"The welded punch's pressure"), the reference's pointwise p taken at the same nodes with the same area
weights; each ring's relative difference is extrapolated over the meshes as the stiffness is (order measured with three
meshes, --pressure-order with two). Boussinesq's frictionless p(r) = P / (2 pi a sqrt(a^2 - r^2)) is shown
beside it, with whether the tolerance tells the two apart.

  /usr/bin/python3 compare.py --domain OUT_n4_L10 OUT_n4_L20 OUT_n4_L40 --mesh 4:OUT_n4_L10 8:OUT_n8_L10 \
      [16:OUT_n16_L10] --tolerance 0.02 [--plot FIG.png] [--pressure-tolerance 0.05 [--pressure-order 0.78]
      --pressure-plot FIG.png]
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


RINGS = [(0.0, 0.2), (0.2, 0.4), (0.4, 0.6), (0.6, 0.8)]  # r / a, away from the edge singularity
QUAD = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]  # hex8 faces


def top_areas(X, C, top):
    """[node] the tributary area of each top-surface node, the integral of its shape function over the
    top faces (2 x 2 Gauss on each bilinear quad, projected on the plane z = const), m^2."""
    area = np.zeros(len(X))
    g = np.array([-1.0, 1.0]) / math.sqrt(3.0)
    for element in C:
        for face in QUAD:
            q = element[list(face)]
            if not np.all(top[q]):
                continue
            x, y = X[q, 0], X[q, 1]
            for xi in g:
                for eta in g:
                    N = 0.25 * np.array([(1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta)])
                    dxi = 0.25 * np.array([-(1 - eta), 1 - eta, 1 + eta, -(1 + eta)])
                    deta = 0.25 * np.array([-(1 - xi), -(1 + xi), 1 + xi, 1 - xi])
                    area[q] += N * abs(dxi @ x * (deta @ y) - deta @ x * (dxi @ y))
    return area


def welded_reference():
    """The welded punch's pressure on the half-space at nu = NU (welded_punch.py, 128 rings: within 1e-5 of
    512 rings at r <= 0.9 a; README.md, "The welded punch's pressure"), solved once."""
    global _WELDED
    if _WELDED is None:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import welded_punch
        _WELDED = (welded_punch, welded_punch.solve(NU, 128))
    return _WELDED


_WELDED = None


def ring_pressures(out):
    """(P, [ring] tribex's mean pressure, {"welded", "boussinesq"}: [ring] the reference's mean over the same
    nodes and areas, node radii and pressures) of one run: the last results.h5 step's rigid_body_force on
    the punch nodes. Both references are for the run's own total force P."""
    import h5py
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
    from results_h5 import si
    with h5py.File(os.path.join(out, "run", "results.h5"), "r") as f:
        X, C = si(f["mesh/coordinates"]), f["mesh/connectivity"][()]
        c = f["steps"][sorted(f["steps"].keys())[-1]]["nodal/rigid_body_force"][()]
    top = np.abs(X[:, 2] - X[:, 2].max()) < 1e-6 * A
    punch = np.nonzero(np.abs(c).sum(axis=1))[0]
    area = top_areas(X, C, top)[punch]
    force = -c[punch, 2]  # the punch pushes down: -c_z into the body
    P, r, p = force.sum(), np.hypot(X[punch, 0], X[punch, 1]), force / area
    inner = r < 0.999 * A  # the references are singular at the edge; the rings stop at 0.8 a
    module, sol = welded_reference()
    pointwise = {"boussinesq": P / (2 * math.pi * A * np.sqrt(np.maximum(A * A - r * r, 1e-300))),
                 "welded": np.where(inner, module.pressure(sol, np.minimum(r / A, 0.999))[0], 0)
                 * P / (2 * math.pi * A * A)}
    fe, ref = [], {k: [] for k in pointwise}
    for lo, hi in RINGS:
        m = (r >= lo * A * (1 - 1e-9)) & (r < hi * A * (1 - 1e-9))
        fe.append(force[m].sum() / area[m].sum())
        for k, v in pointwise.items():
            ref[k].append((v[m] * area[m]).sum() / area[m].sum())
    return P, np.array(fe), {k: np.array(v) for k, v in ref.items()}, r, p


def extrapolate(cells, diff, order):
    """Richardson over the meshes, ring by ring: (extrapolated, order), the order measured with three meshes,
    else `order`."""
    if len(cells) >= 3:
        order = np.log((diff[-3] - diff[-2]) / (diff[-2] - diff[-1])) / math.log(cells[-2] / cells[-3])
    else:
        order = np.full(len(RINGS), order)
    return diff[-1] + (diff[-1] - diff[-2]) / ((cells[-1] / cells[-2]) ** order - 1), order


def pressure_check(meshes, tolerance, order, plot):
    """Ring by ring, tribex's pressure / the welded punch's - 1 per mesh, extrapolated over the meshes; 0 if
    every ring's extrapolated difference is within `tolerance`, else 1. Boussinesq's frictionless punch is
    shown beside it, to say whether the check tells the two apart."""
    cells, diff, free, runs = [], [], [], []
    for item in meshes:
        n, out = item.split(":", 1)
        P, fe, ref, r, p = ring_pressures(out)
        cells.append(int(n))
        diff.append(fe / ref["welded"] - 1)
        free.append(fe / ref["boussinesq"] - 1)
        runs.append((int(n), P, r, p))
        rings = ", ".join(f"{lo:.1f}-{hi:.1f} a {100 * d:+.2f} % ({100 * b:+.2f} %)"
                          for (lo, hi), d, b in zip(RINGS, diff[-1], free[-1]))
        print(f"pressure, mesh n = {n:>2} (P = {P * 1e9:.2f} nN), from the welded punch (from Boussinesq): {rings}")
    gap = ref["welded"] / ref["boussinesq"] - 1
    print("pressure, welded / Boussinesq - 1 on the finest mesh's rings: "
          + ", ".join(f"{100 * g:+.2f} %" for g in gap)
          + f" ({'beyond' if np.any(np.abs(gap) > tolerance) else 'NOT beyond'} the tolerance in some ring: "
          + f"the check {'separates' if np.any(np.abs(gap) > tolerance) else 'does not separate'} the two)")
    extrapolated, orders = extrapolate(cells, np.array(diff), order)
    free_extrapolated, _ = extrapolate(cells, np.array(free), order)
    for (lo, hi), e, b, o in zip(RINGS, extrapolated, free_extrapolated, orders):
        print(f"pressure, ring {lo:.1f}-{hi:.1f} a: extrapolated {100 * e:+.2f} % from the welded punch "
              f"(order {o:.2f}, "
              f"tolerance {100 * tolerance:.1f} %; {100 * b:+.2f} % from Boussinesq)")
    if plot:
        plot_pressure(runs, plot)
    bad = np.abs(extrapolated) > tolerance
    if bad.any():
        print(f"FAIL: the pressure of {int(bad.sum())} ring(s) outside {100 * tolerance:.1f} %")
        return 1
    return 0


def plot_pressure(runs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for n, P, r, p in runs:
        order = np.argsort(r)
        ax.plot(r[order] / A, p[order] / 1e9, ".", ms=4, label=f"tribex, {n} cells across a (P = {P * 1e9:.1f} nN)")
    s = np.linspace(0, 0.995, 200)
    P = runs[-1][1]
    module, sol = welded_reference()
    ax.plot(s, module.pressure(sol, s)[0] * P / (2 * math.pi * A * A) / 1e9, "k-", lw=1,
            label="welded punch (welded_punch.py), P of the finest mesh")
    ax.plot(s, P / (2 * math.pi * A * A * np.sqrt(1 - s * s)) / 1e9, "k--", lw=0.8,
            label="Boussinesq (frictionless), same P")
    ax.axvline(0.8, color="grey", ls=":", lw=0.8, label="compared: r < 0.8 a")
    ax.set_xlabel("r / a (a = 10 nm)")
    ax.set_ylabel("pressure under the punch (GPa)")
    ax.set_ylim(0, 2.5)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print("wrote", path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--domain", nargs=3, required=True, help="one mesh at L = 10, 20, 40")
    ap.add_argument("--mesh", nargs="+", required=True, help="CELLS:OUT at L = 10, two or three meshes")
    ap.add_argument("--tolerance", type=float, default=0.02)
    ap.add_argument("--plot")
    ap.add_argument("--pressure-tolerance", type=float, help="also check the pressure under the punch, ring by ring")
    ap.add_argument("--pressure-order", type=float, default=1.0,
                    help="the pressure's convergence order for two meshes (three measure it; default 1)")
    ap.add_argument("--pressure-plot")
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
    failed = abs(error) > a.tolerance
    if failed:
        print(f"FAIL: {100 * error:+.2f} % outside {100 * a.tolerance:.1f} %")
    if a.pressure_tolerance is not None and pressure_check(a.mesh, a.pressure_tolerance, a.pressure_order,
                                                           a.pressure_plot):
        failed = True
    if failed:
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
