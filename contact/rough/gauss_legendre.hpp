// SPDX-License-Identifier: MIT
// Gauss-Legendre rules: the fixed rule of the GW integrals (gw_integrals.cpp, report Eq. 4.9; docs/theory.md 10) and the
// rules of the layered-contact tool's Hankel-space and Abel integrals (tools/layered, docs/theory.md 11.4.3).
#pragma once

#include <vector>

namespace tribex::gw {

struct QuadratureRule {
  std::vector<double> x, w;
};

/// n-point Gauss-Legendre on [lo, hi] (nodes by Newton iteration on P_n; exact for degree 2n - 1).
QuadratureRule gauss_legendre_rule(int n, double lo, double hi);

/// Composite Gauss-Legendre: `panels` equal panels of `per_panel` points on [lo, hi].
QuadratureRule composite_gauss_legendre_rule(int panels, int per_panel, double lo, double hi);

}  // namespace tribex::gw
