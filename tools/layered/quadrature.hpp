// SPDX-License-Identifier: MIT
// Gauss-Legendre rules and the composite rule for the Hankel-space integrals of the contact solver
// (docs/theory.md 11.4.3).
#pragma once

#include <vector>

namespace tribex::layered {

struct Rule {
  std::vector<double> x, w;
};

/// n-point Gauss-Legendre on [lo, hi] (nodes by Newton iteration on P_n; exact for degree 2n - 1).
Rule gauss_legendre(int n, double lo, double hi);

/// Composite Gauss-Legendre: `panels` equal panels of `per_panel` points on [lo, hi].
Rule composite_gauss_legendre(int panels, int per_panel, double lo, double hi);

}  // namespace tribex::layered
