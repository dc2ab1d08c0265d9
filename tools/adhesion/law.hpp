// SPDX-License-Identifier: MIT
// The surface pressure of the reference as a function of the gap, the law of `model = adhesion`
// (docs/theory.md 6.2-6.3, contact/models/adhesion_lj.hpp) with its hard contact made a stiff
// penalty (docs/theory.md 6.7.1, Eq. 6.7.1):
//   p(g) = -sigma_s(g)                      0 <= g <= g_c   (sigma_s the offset, cut-off, shifted LJ 3-9 law)
//   p(g) = sigma_a(h_c) - k g               g < 0           (k = kappa E*/z0; continuous at g = 0)
//   p(g) = 0                                g > g_c
// p is positive in compression (pushing the surfaces apart).
#pragma once

#include "contact/models/adhesion_lj.hpp"

namespace tribex::adhesion {

struct GapLaw {
  contact::AdhesionLaw law;  // W, z0, h_c exactly as the contact model takes them
  double penalty = 0;        // k, Pa/m

  /// p(g), Pa, compressive positive.
  double pressure(double gap) const {
    if (gap < 0) return shift() - penalty * gap;
    return -contact::adhesive_traction(gap, law);
  }
  /// dp/dg, Pa/m.
  double slope(double gap) const {
    if (gap < 0) return -penalty;
    if (gap > law.capture_gap() || law.work == 0) return 0.0;
    const double h = gap + law.z0, x = law.z0 / h, x3 = x * x * x;
    // d sigma_a/dh = (8W/(3 z0)) (-3 x^3 + 9 x^9)/h
    return -8.0 * law.work / (3.0 * law.z0) * (-3.0 * x3 + 9.0 * x3 * x3 * x3) / h;
  }
  /// sigma_a(h_c): the small repulsion the shift leaves at touching (docs/theory.md 6.2).
  double shift() const {
    return law.work == 0 ? 0.0 : contact::lj_traction(law.cutoff, law.work, law.z0);
  }
  /// The work the applied law captures, -U(z0) (docs/theory.md 6.3), J/m^2.
  double captured_work() const { return law.work == 0 ? 0.0 : contact::captured_work(law); }
};

}  // namespace tribex::adhesion
