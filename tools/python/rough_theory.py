# SPDX-License-Identifier: MIT
"""Greenwood-Williamson pieces the rough-surface compare scripts evaluate directly, independently of
the C++ tables (scipy quadrature): the integrals F_n(t) (report Eq. 4.9) and the attraction of the
non-contacting area (docs/theory.md 10.8): the Lennard-Jones 3-9 law with W, z0 and cut-off h_c
(shifted to zero at h_c) averaged over Gaussian surface heights of deviation sigma at mean-plane
separation d, the touching part (z >= d) excluded.
"""
import math

from scipy import integrate


def gw_integral(n, t):
    """F_n(t) = (1/sqrt(2 pi)) int_t^inf (s - t)^n exp(-s^2/2) ds."""
    value, _ = integrate.quad(lambda s: (s - t) ** n * math.exp(-0.5 * s * s), t, t + 40.0, epsabs=0, epsrel=1e-12,
                              limit=200)
    return value / math.sqrt(2.0 * math.pi)


def lj_traction(h, W, z0):
    """sigma_a(h) = (8 W / (3 z0)) [(z0/h)^3 - (z0/h)^9], Pa (docs/theory.md 6)."""
    r3 = (z0 / h) ** 3
    return 8.0 * W / (3.0 * z0) * (r3 - r3 ** 3)


def noncontact_attraction(d, W, z0, cutoff, sigma):
    """int_0^{h_c - z0} [sigma_a(g + z0) - sigma_a(h_c)] phi((d - g)/sigma) / sigma dg, Pa (>= 0 attracts)."""
    shift = lj_traction(cutoff, W, z0)

    def f(g):
        x = (d - g) / sigma
        return (lj_traction(g + z0, W, z0) - shift) * math.exp(-0.5 * x * x) / (sigma * math.sqrt(2 * math.pi))
    lo, hi = max(0.0, d - 10 * sigma), min(cutoff - z0, d + 10 * sigma)
    if hi <= lo:
        return 0.0
    value, _ = integrate.quad(f, lo, hi, points=[p for p in (z0, 5 * z0, d) if lo < p < hi], epsabs=0, epsrel=1e-10,
                              limit=400)
    return value
