#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The rigid flat circular punch (radius a, depth delta) on an elastic half-space (shear modulus G, Poisson's
ratio nu), bonded ("welded": u_z = delta and u_r = 0 for r <= a) or frictionless (u_z = delta, no shear):
a boundary-element solution on the contact disc. It is the reference for the pressure under the welded
punch of verification/rigid_punch (compare.py).

Unknowns. The normal pressure p(r) (positive pushing into the body) and the radial shear traction q(r)
(positive outward) that the punch puts on the surface, on N rings uniform in theta (r = a sin theta, so the
rings crowd toward the edge), each of the form

    p(r) = phi_j w(r),   q(r) = psi_j w(r),   w(r) = (1 - r^2/a^2)^(-alpha),   theta_j <= theta < theta_j+1,

alpha = 1/2 by default: the square-root edge singularity of the flat punch (p ~ (a^2 - r^2)^(-1/2)) is in
the weight, so phi and psi are bounded (for the welded punch they carry the slow oscillation of the bonded
edge, (a - r)^(i eps) with eps = ln(3 - 4 nu)/(2 pi) = 0.094 at nu = 0.3, which the rings resolve). Frictionless, Boussinesq's
p = P/(2 pi a sqrt(a^2 - r^2)) is phi = constant: any N reproduces it (to the quadrature). alpha = 0 gives
plain piecewise-constant rings, whose convergence in N the tests show on the frictionless punch.

Green's functions: the surface displacements at radius r from a ring load of unit total force at radius s
(Boussinesq's normal and Cerruti's tangential point load, Johnson, Contact Mechanics (1985) ch. 3,
integrated around the ring; equivalently the Hankel-transform solution of the half-space, whose
Weber-Schafheitlin integrals of J0 J0 and J1 J1 give the elliptic integrals):

    normal ring -> u_z:  Gzz = (1 - nu)/(pi^2 G) K(k)/(r + s)                       k^2 = 4 r s/(r + s)^2
    radial ring -> u_r:  Grr = (1 - nu)/(2 pi^2 G) (r + s)/(r s) [(1 - k^2/2) K(k) - E(k)]
    normal ring -> u_r:  Grz = -(1 - 2 nu)/(4 pi G r)   for s < r, 0 for s > r  (Boussinesq's u_r outside
                                                                                  the ring, none inside)
    radial ring -> u_z:  Gzr = -(1 - 2 nu)/(4 pi G s)   for s > r, 0 for s < r  (Betti: Gzr(r,s) = Grz(s,r))

(K, E complete elliptic integrals; u_z positive into the body, u_r outward). Far from the ring Gzz -> (1 -
nu)/(2 pi G r), Boussinesq's point load, and Grr -> (1 - nu) s/(4 pi G r^2). The ring integrals are done in
theta on each ring, split at the collocation radius (where Gzz and Grr are log-singular and Grz, Gzr jump),
with the substitution theta = t^3 (10 - 15 t + 6 t^2) at both ends of each piece and Gauss-Legendre in t.

Collocation at the middle (in theta) of each ring: u_z(r_i) = delta, and u_r(r_i) = 0 (welded) or psi = 0
(frictionless). The total force P = sum_j 2 pi int p r dr; the stiffness K = P/delta. Checks against
(tests in CMakeLists.txt, figures in README.md): frictionless K = 2 a E/(1 - nu^2) = 4 G a/(1 - nu)
(Boussinesq 1885, Sneddon 1946) and Boussinesq's p(r); welded at nu = 1/2 = frictionless (no coupling,
1 - 2 nu = 0); welded K = 4 G a ln(3 - 4 nu)/(1 - 2 nu) (Mossakovskii 1954), which the rings reach to 3e-8.

  /usr/bin/python3 welded_punch.py --nu 0.3 --rings 128 --csv welded.csv      # the welded punch
  /usr/bin/python3 welded_punch.py --nu 0.3 --frictionless                    # Boussinesq's punch

The CSV gives r/a and p, q normalised by P/(2 pi a^2) (dimensionless; Boussinesq's p is 1/sqrt(1 - r^2/a^2)),
and p sqrt(1 - r^2/a^2) likewise; the header comment lines give K/(G a) and the run's settings.
"""
import argparse
import math
import sys

import numpy as np
from scipy import special

GAUSS = 16  # Gauss-Legendre points per piece: the frictionless punch's K to 3e-8 at 16 rings, its p to 1e-12


def ring_greens(r, s, nu):
    """(Gzz, Grr, Grz, Gzr) at radius r from a ring of unit total force at radius s, for G = 1 (see the
    module docstring); r, s arrays of one shape, r != s."""
    m1 = ((r - s) / (r + s)) ** 2  # 1 - k^2, kept apart so that K is accurate near r = s (ellipkm1)
    K, E = special.ellipkm1(m1), special.ellipe(1.0 - m1)
    k2 = 1.0 - m1
    gzz = (1 - nu) / (math.pi ** 2) * K / (r + s)
    grr = (1 - nu) / (2 * math.pi ** 2) * (r + s) / (r * s) * ((1 - 0.5 * k2) * K - E)
    grz = np.where(s < r, -(1 - 2 * nu) / (4 * math.pi * r), 0.0)
    gzr = np.where(s > r, -(1 - 2 * nu) / (4 * math.pi * s), 0.0)
    return gzz, grr, grz, gzr


def _piece_rule(lo, hi):
    """Nodes and weights in theta for the pieces [lo, hi] (arrays of one shape): theta = lo + (hi - lo) g(t)
    with g = t^3 (10 - 15 t + 6 t^2), whose g' ~ t^2 at both ends tames a log singularity there."""
    t, wt = np.polynomial.legendre.leggauss(GAUSS)
    t, wt = 0.5 * (t + 1), 0.5 * wt
    g = t ** 3 * (10 - 15 * t + 6 * t * t)
    dg = 30 * t * t * (1 - t) ** 2
    span = (hi - lo)[..., None]
    return lo[..., None] + span * g, span * dg * wt


def influence(edges, rc, nu, alpha):
    """[4][i, j] u_z and u_r at the collocation radii rc[i] (a = 1) from unit phi or psi on ring j:
    (zz, zr, rz, rr) = (u_z from p, u_z from q, u_r from p, u_r from q)."""
    tc = np.arcsin(rc)
    lo = np.broadcast_to(edges[:-1][None, :], (len(rc), len(edges) - 1))
    hi = np.broadcast_to(edges[1:][None, :], lo.shape)
    cut = np.clip(tc[:, None], lo, hi)  # the collocation angle inside the ring, or the nearer end
    out = [np.zeros(lo.shape) for _ in range(4)]
    for a, b in ((lo, cut), (cut, hi)):
        th, wq = _piece_rule(a, b)
        s = np.sin(th)
        # the load on d theta: 2 pi s w(s) ds = 2 pi sin(theta) cos(theta)^(1 - 2 alpha) d theta
        load = 2 * math.pi * s * np.cos(th) ** (1 - 2 * alpha) * wq
        r = np.broadcast_to(rc[:, None, None], s.shape)
        for k, g in enumerate(ring_greens(r, s, nu)):
            order = (0, 3, 2, 1)[k]  # ring_greens gives (zz, rr, rz, zr)
            out[order] += (g * load).sum(axis=-1)
    return out


def solve(nu, rings, welded=True, alpha=0.5):
    """The punch of radius 1 pressed 1 deep into a half-space with G = 1: a dict with K (= K/(G a)), the ring
    edges and collocation radii (r/a), phi and psi there (p = phi w(r), q = psi w(r)) and alpha."""
    edges = np.linspace(0.0, 0.5 * math.pi, rings + 1)  # theta
    tc = 0.5 * (edges[:-1] + edges[1:])
    rc = np.sin(tc)
    zz, zr, rz, rr = influence(edges, rc, nu, alpha)
    n = rings
    if welded:
        A = np.block([[zz, zr], [rz, rr]])
        b = np.concatenate([np.ones(n), np.zeros(n)])
        x = np.linalg.solve(A, b)
        phi, psi = x[:n], x[n:]
    else:
        phi, psi = np.linalg.solve(zz, np.ones(n)), np.zeros(n)
    # P = sum_j phi_j 2 pi int sin cos^(1 - 2 alpha) d theta = 2 pi phi_j [-cos^(2 - 2 alpha)/(2 - 2 alpha)]
    m = 2 - 2 * alpha
    P = 2 * math.pi * np.sum(phi * (np.cos(edges[:-1]) ** m - np.cos(edges[1:]) ** m) / m)
    return {"K": P, "P": P, "edges": np.sin(edges), "rc": rc, "phi": phi, "psi": psi, "alpha": alpha,
            "theta_edges": edges, "theta_c": tc}


def pressure(sol, r):
    """(p, q) / (P/(2 pi a^2)) at r/a (array, r < 1): phi and psi interpolated linearly in theta between the
    collocation points, times the weight w(r). Below the first point p is even in r and q odd (q(0) = 0 by
    symmetry), so phi and psi are continued to theta < 0 as such; beyond the last they are held."""
    r = np.asarray(r, dtype=float)
    th = np.arcsin(np.clip(r, 0.0, 1.0))
    w = (1.0 - r * r) ** (-sol["alpha"])
    scale = 2 * math.pi / sol["P"]  # P/(2 pi a^2) with a = 1
    tc = np.concatenate([[-sol["theta_c"][0]], sol["theta_c"]])
    p = np.interp(th, tc, np.concatenate([[sol["phi"][0]], sol["phi"]])) * w * scale
    q = np.interp(th, tc, np.concatenate([[-sol["psi"][0]], sol["psi"]])) * w * scale
    return p, q


def mossakovskii_K(nu):
    """K/(G a) of the welded punch, 4 ln(3 - 4 nu)/(1 - 2 nu) (8 at nu = 1/2)."""
    return 8.0 if abs(nu - 0.5) < 1e-12 else 4 * math.log(3 - 4 * nu) / (1 - 2 * nu)


def boussinesq_K(nu):
    """K/(G a) of the frictionless punch, 2 a E/(1 - nu^2) = 4 G a/(1 - nu)."""
    return 4.0 / (1 - nu)


def write_csv(path, sol, nu, welded, points):
    r = np.linspace(0.0, 1.0, points, endpoint=False)
    p, q = pressure(sol, r)
    kind = "welded" if welded else "frictionless"
    with open(path, "w") as f:
        f.write(f"# {kind} rigid flat punch on a half-space, nu = {nu:g}, {len(sol['phi'])} rings "
                f"(welded_punch.py); K/(G a) = {sol['K']:.8g}\n")
        f.write("# p, q normalised by P/(2 pi a^2); p_sqrt = p sqrt(1 - (r/a)^2) (1 for Boussinesq's punch)\n")
        f.write("r_over_a [1],p_norm [1],q_norm [1],p_sqrt_norm [1]\n")
        for ri, pi_, qi in zip(r, p, q):
            f.write(f"{ri:.6f},{pi_:.8f},{qi:.8f},{pi_ * math.sqrt(1 - ri * ri):.8f}\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio, 0 <= nu <= 0.5 (default 0.3)")
    ap.add_argument("--rings", type=int, default=128, help="rings on the contact disc (default 128)")
    ap.add_argument("--frictionless", action="store_true", help="no shear under the punch (default: welded)")
    ap.add_argument("--plain", action="store_true", help="piecewise-constant p, q (no edge weight)")
    ap.add_argument("--csv", help="write p(r), q(r) on a grid to this CSV")
    ap.add_argument("--points", type=int, default=100, help="grid points of the CSV, r/a = 0, 1/points, ... < 1")
    ap.add_argument("--radius", type=float, default=10e-9, help="a in m, for K and P in SI (default 10e-9)")
    ap.add_argument("--youngs", type=float, default=100e9, help="E in Pa (default 100e9)")
    ap.add_argument("--depth", type=float, default=0.1e-9, help="delta in m (default 0.1e-9)")
    a = ap.parse_args(argv)
    if not 0.0 <= a.nu <= 0.5 or a.rings < 1 or a.points < 2 or min(a.radius, a.youngs, a.depth) <= 0:
        print(f"welded_punch.py: error: need 0 <= nu <= 0.5, rings >= 1, "
              f"points >= 2, positive radius, youngs, depth (got nu = {a.nu}, rings = {a.rings}, points = {a.points}, "
              f"radius = {a.radius}, youngs = {a.youngs}, depth = {a.depth})", file=sys.stderr)
        return 2
    welded = not a.frictionless
    sol = solve(a.nu, a.rings, welded, 0.0 if a.plain else 0.5)
    ref = mossakovskii_K(a.nu) if welded else boussinesq_K(a.nu)
    name = "Mossakovskii" if welded else "Boussinesq"
    print(f"{'welded' if welded else 'frictionless'} punch, nu = {a.nu:g}, {a.rings} rings: K/(G a) = "
          f"{sol['K']:.8g}; {name} {ref:.8g} ({100 * (sol['K'] / ref - 1):+.4f} %)")
    K = sol["K"] * a.youngs / (2 * (1 + a.nu)) * a.radius
    print(f"a = {a.radius:g} m, E = {a.youngs:g} Pa: K = {K:.6g} N/m, P = {K * a.depth:.6g} N at delta = {a.depth:g} m")
    if a.csv:
        write_csv(a.csv, sol, a.nu, welded, a.points)
        print("wrote", a.csv)
    return 0


if __name__ == "__main__":
    sys.exit(main())
