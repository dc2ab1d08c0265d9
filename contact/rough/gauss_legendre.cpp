// SPDX-License-Identifier: MIT
#include "contact/rough/gauss_legendre.hpp"

#include <cmath>
#include <numbers>

namespace tribex::gw {

QuadratureRule gauss_legendre_rule(int n, double lo, double hi) {
  QuadratureRule r;
  r.x.resize(n);
  r.w.resize(n);
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));  // Tricomi's first guess
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1, then the three-term recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    r.x[i] = mid - half * x;
    r.x[n - 1 - i] = mid + half * x;
    r.w[i] = r.w[n - 1 - i] = half * w;
  }
  return r;
}

QuadratureRule composite_gauss_legendre_rule(int panels, int per_panel, double lo, double hi) {
  QuadratureRule out;
  const double width = (hi - lo) / panels;
  for (int p = 0; p < panels; ++p) {
    const QuadratureRule g = gauss_legendre_rule(per_panel, lo + p * width, lo + (p + 1) * width);
    out.x.insert(out.x.end(), g.x.begin(), g.x.end());
    out.w.insert(out.w.end(), g.w.begin(), g.w.end());
  }
  return out;
}

}  // namespace tribex::gw
