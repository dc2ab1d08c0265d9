#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks of welded_punch.py, the reference for the pressure under the welded punch (README.md, "The
welded punch's pressure"); each prints its figures and exits 1 if one is outside its tolerance (stated with each).

  /usr/bin/python3 test_welded_punch.py greens|frictionless|incompressible|mossakovskii|convergence

greens:         the ring Green's functions against Boussinesq's and Cerruti's point loads integrated
                around the ring numerically (Johnson, Contact Mechanics (1985) ch. 3).
frictionless:   K = 4 G a/(1 - nu) and p = P/(2 pi a sqrt(a^2 - r^2)) (Boussinesq): with the edge weight
                exact for any number of rings; with plain rings converging in their number.
incompressible: welded at nu = 1/2 is the frictionless punch (the coupling 1 - 2 nu vanishes).
mossakovskii:   welded K against 4 G a ln(3 - 4 nu)/(1 - 2 nu) at nu = 0 ... 0.45, converged in the rings.
convergence:    the welded p(r) at fixed r as the rings double, and plain rings (no edge weight) agreeing.
"""
import math
import os
import sys

import numpy as np
from scipy import integrate

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import welded_punch as wp  # noqa: E402

FAILED = []


def check(what, value, tolerance):
    ok = abs(value) <= tolerance
    print(f"  {what}: {value:+.3e} (tolerance {tolerance:.0e}) {'ok' if ok else 'FAIL'}")
    if not ok:
        FAILED.append(what)


def ring_point_load(r, s, nu, kind):
    """u_z (kind 'zz', 'zr') or u_r ('rz', 'rr') at (r, 0) from a ring of unit total force at radius s, normal
    ('?z') or radial outward ('?r'), by integrating the point-load surface displacements (G = 1) around it."""
    def integrand(t):
        d = np.array([r - s * math.cos(t), -s * math.sin(t)])  # from the source point to (r, 0)
        rho = math.hypot(*d)
        if kind == "zz":  # Boussinesq: u_z = (1 - nu) F/(2 pi G rho)
            return (1 - nu) / (2 * math.pi * rho)
        if kind == "rz":  # Boussinesq: u = -(1 - 2 nu) F/(4 pi G rho) toward the load
            return -(1 - 2 * nu) / (4 * math.pi * rho) * d[0] / rho
        e = np.array([math.cos(t), math.sin(t)])  # the load's direction, radial at the source
        if kind == "rr":  # Cerruti: u = F/(2 pi G) [(1 - nu) e/rho + nu (e.d) d/rho^3], its x component
            return ((1 - nu) * e[0] / rho + nu * (e @ d) * d[0] / rho ** 3) / (2 * math.pi)
        # 'zr': Cerruti's u_z = (1 - 2 nu) F (e.d)/(4 pi G rho^2), into the body ahead of the load (Betti with
        # Boussinesq's u_r toward a normal load)
        return (1 - 2 * nu) / (4 * math.pi) * (e @ d) / rho ** 2
    v, _ = integrate.quad(integrand, 0.0, 2 * math.pi, points=[math.pi], limit=400, epsabs=1e-13, epsrel=1e-12)
    return v / (2 * math.pi)


def greens():
    print("greens: ring Green's functions / point loads integrated around the ring - 1")
    for nu in (0.0, 0.3, 0.45):
        for r, s in ((1.0, 0.5), (0.3, 0.9), (1.0, 0.97), (0.05, 0.8)):
            g = dict(zip(("zz", "rr", "rz", "zr"), wp.ring_greens(np.array(r), np.array(s), nu)))
            for kind in ("zz", "rr", "rz", "zr"):
                ref = ring_point_load(r, s, nu, kind)
                err = float(g[kind]) - ref if abs(ref) < 1e-14 else float(g[kind]) / ref - 1
                check(f"nu {nu}, r {r}, s {s}, G{kind}", err, 1e-8)


def frictionless():
    print("frictionless: K/(4 G a/(1 - nu)) - 1 and max |p/p_Boussinesq - 1| over r/a in [0, 0.95]")
    r = np.linspace(0.0, 0.95, 20)
    exact = 1 / np.sqrt(1 - r * r)
    for nu in (0.0, 0.3, 0.45):
        sol = wp.solve(nu, 16, welded=False)
        p, _ = wp.pressure(sol, r)
        check(f"nu {nu}, 16 weighted rings, K", sol["K"] / wp.boussinesq_K(nu) - 1, 1e-7)
        check(f"nu {nu}, 16 weighted rings, p", np.max(np.abs(p / exact - 1)), 1e-7)
    print("frictionless, plain rings (p constant on each), nu = 0.3: error in K and in p at r/a = 0, 0.5")
    previous = None
    for n in (8, 16, 32, 64):
        sol = wp.solve(0.3, n, welded=False, alpha=0.0)
        p, _ = wp.pressure(sol, np.array([0.0, 0.5]))
        err = np.array([sol["K"] / wp.boussinesq_K(0.3) - 1, *(p / (1 / np.sqrt(1 - np.array([0.0, 0.25]))) - 1)])
        print(f"  {n:>3} rings: K {err[0]:+.3e}, p(0) {err[1]:+.3e}, p(0.5 a) {err[2]:+.3e}")
        if previous is not None and np.any(np.abs(err) > np.abs(previous) / 2):
            FAILED.append(f"plain rings {n}: the error did not halve")
            print("  FAIL: an error did not at least halve as the rings doubled")
        previous = err
    check("64 plain rings, K", previous[0], 1e-6)
    check("64 plain rings, p(0)", previous[1], 1e-4)
    check("64 plain rings, p(0.5 a)", previous[2], 1e-4)


def incompressible():
    print("incompressible: welded / frictionless at nu = 0.5")
    welded, free = wp.solve(0.5, 32, welded=True), wp.solve(0.5, 32, welded=False)
    check("K welded / K frictionless - 1", welded["K"] / free["K"] - 1, 1e-12)
    check("max |phi welded - phi frictionless| / phi", np.max(np.abs(welded["phi"] / free["phi"] - 1)), 1e-12)
    check("max |q| / max p", np.max(np.abs(welded["psi"])) / np.max(free["phi"]), 1e-12)
    check("K / 8 G a - 1", welded["K"] / 8 - 1, 1e-7)


def mossakovskii():
    print("mossakovskii: welded K / (4 G a ln(3 - 4 nu)/(1 - 2 nu)) - 1; 64, 128, 256 rings, order measured")
    for nu in (0.0, 0.1, 0.2, 0.3, 0.4, 0.45):
        K = np.array([wp.solve(nu, n)["K"] for n in (64, 128, 256)])
        order = math.log((K[0] - K[1]) / (K[1] - K[2])) / math.log(2)
        extrapolated = K[2] + (K[2] - K[1]) / (2 ** order - 1)
        ref = wp.mossakovskii_K(nu)
        print(f"  nu {nu}: 64 {K[0] / ref - 1:+.3e}, 128 {K[1] / ref - 1:+.3e}, 256 {K[2] / ref - 1:+.3e}, "
              f"order {order:.2f}; welded / frictionless {ref / wp.boussinesq_K(nu):.5f}")
        check(f"nu {nu}, 256 rings", K[2] / ref - 1, 3e-6)
        check(f"nu {nu}, extrapolated", extrapolated / ref - 1, 1e-7)


def convergence():
    print("convergence: welded p/(P/(2 pi a^2)) at nu = 0.3 against 512 rings")
    r = np.array([0.0, 0.3, 0.5, 0.7, 0.8, 0.9])
    fine, _ = wp.pressure(wp.solve(0.3, 512), r)
    print("  r/a:          " + "  ".join(f"{x:>10.2f}" for x in r))
    print("  512 rings p:  " + "  ".join(f"{x:>10.6f}" for x in fine))
    previous = None
    for n in (32, 64, 128, 256):
        p, _ = wp.pressure(wp.solve(0.3, n), r)
        err = np.abs(p / fine - 1)
        print(f"  {n:>3} rings:    " + "  ".join(f"{x:>10.2e}" for x in err))
        if previous is not None and np.any(err > previous):
            FAILED.append(f"{n} rings: p did not converge monotonically")
        previous = err
    p128, _ = wp.pressure(wp.solve(0.3, 128), r)
    # compare.py's tolerances are per cent; 5e-5 keeps the reference's own error 20 times under 0.1 %
    check("128 rings (compare.py's), max |p/p_512 - 1|", np.max(np.abs(p128 / fine - 1)), 5e-5)
    # The weight is a choice, not an assumption: plain rings (p, q constant on each) reach the same punch.
    plain = wp.solve(0.3, 256, alpha=0.0)
    p_plain, _ = wp.pressure(plain, r[:-1])  # r <= 0.8 a, where compare.py looks
    print("  256 plain rings: " + "  ".join(f"{x:>10.2e}" for x in np.abs(p_plain / fine[:-1] - 1)))
    check("256 plain rings, K / Mossakovskii - 1", plain["K"] / wp.mossakovskii_K(0.3) - 1, 1e-6)
    check("256 plain rings, max |p/p_512 - 1| for r <= 0.8 a", np.max(np.abs(p_plain / fine[:-1] - 1)), 5e-5)


def main():
    checks = {f.__name__: f for f in (greens, frictionless, incompressible, mossakovskii, convergence)}
    names = sys.argv[1:] or list(checks)
    for name in names:
        if name not in checks:
            print(f"test_welded_punch.py: error: unknown check '{name}' (one of {', '.join(checks)})", file=sys.stderr)
            return 2
        checks[name]()
    if FAILED:
        print(f"FAIL: {len(FAILED)} check(s): {'; '.join(FAILED)}")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
