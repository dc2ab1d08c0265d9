// SPDX-License-Identifier: MIT
// docs/theory.md 6.7.2 (Eq. 6.7.3): exact ring influence of the axisymmetric Boussinesq problem.
#include "tools/adhesion/kernel.hpp"

#include <cmath>

namespace tribex::adhesion {
namespace {

// K(k) and E(k) by the arithmetic-geometric mean (Abramowitz & Stegun 17.6), to round-off; k < 1.
void elliptic_ke(double k, double& kk, double& ee) {
  double a = 1.0, b = std::sqrt((1.0 - k) * (1.0 + k)), c2sum = 0.5 * k * k, pow2 = 0.5;
  for (int i = 0; i < 40 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double an = 0.5 * (a + b), cn = 0.5 * (a - b);
    b = std::sqrt(a * b);
    a = an;
    pow2 *= 2.0;
    c2sum += pow2 * cn * cn;
  }
  kk = M_PI / (2.0 * a);
  ee = kk * (1.0 - c2sum);
}

}  // namespace

double disk_displacement_scaled(double r, double b) {
  if (b <= 0.0) return 0.0;
  double kk = 0, ee = 0;
  if (r < b) {
    elliptic_ke(r / b, kk, ee);
    return b * ee;
  }
  if (r == b) return b;  // E(1) = 1
  const double k = b / r;
  elliptic_ke(k, kk, ee);
  return r * (ee - (1.0 - k * k) * kk);
}

std::vector<double> ring_influence(const std::vector<double>& points, const std::vector<double>& edges, double e_star) {
  const std::size_t n = points.size(), m = edges.size() - 1;
  std::vector<double> c(n * m);
  const double scale = 4.0 / (M_PI * e_star);
  for (std::size_t i = 0; i < n; ++i) {
    double previous = disk_displacement_scaled(points[i], edges[0]);
    for (std::size_t j = 0; j < m; ++j) {
      const double next = disk_displacement_scaled(points[i], edges[j + 1]);
      c[i * m + j] = scale * (next - previous);
      previous = next;
    }
  }
  return c;
}

}  // namespace tribex::adhesion
