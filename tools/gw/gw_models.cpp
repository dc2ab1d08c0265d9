// SPDX-License-Identifier: MIT
#include "tools/gw/gw_models.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include "contact/rough/gw_integrals.hpp"

namespace tribex::gw {

GwPoint continuous_gw(double t) {
  return {t, gw_integral(0.0, t), gw_integral(1.0, t), gw_integral(1.5, t)};
}

GwPoint discrete_gw(const std::vector<double>& heights, double t) {
  if (heights.empty()) throw std::invalid_argument("discrete_gw: empty population");
  GwPoint p{t, 0.0, 0.0, 0.0};
  for (double z : heights) {
    const double w = z - t;
    if (w <= 0.0) continue;
    p.count += 1.0;
    p.area += w;
    p.load += w * std::sqrt(w);
  }
  const double n = static_cast<double>(heights.size());
  p.count /= n;
  p.area /= n;
  p.load /= n;
  return p;
}

std::vector<double> gaussian_population(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> z(n);
  // Box-Muller written out so the population does not depend on the standard library's normal_distribution.
  for (std::size_t i = 0; i < n; i += 2) {
    const double r = std::sqrt(-2.0 * std::log(1.0 - u(rng))), th = 2.0 * M_PI * u(rng);
    z[i] = r * std::cos(th);
    if (i + 1 < n) z[i + 1] = r * std::sin(th);
  }
  return z;
}

std::vector<double> stratified_gaussian_population(std::size_t n) {
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = normal_quantile((static_cast<double>(i) + 0.5) / static_cast<double>(n));
  return z;
}

namespace {
/// Derjaguin 3-9 attraction of one asperity at gap s, in units of 2 pi W R (positive = attractive).
double gap_attraction(double s, double z0) {
  const double r = z0 / (s + z0);
  return (4.0 / 3.0) * r * r - (1.0 / 3.0) * std::pow(r, 8);
}
}  // namespace

GwPoint dmt_gw(double t, double beta, double z0) {
  GwPoint p = continuous_gw(t);
  p.load -= beta * p.count;  // -2 pi W R per contacting asperity
  if (z0 > 0.0) {
    // Out of contact: z = t - s, s in (0, inf); the 1/s^2 tail needs ~ (t + 10) range and fine panels near 0.
    auto f = [&](double s) { return gap_attraction(s, z0) * normal_pdf(t - s); };
    const double near = gauss_legendre(f, 0.0, 20.0 * z0, 64);
    const double far = gauss_legendre(f, 20.0 * z0, 20.0 * z0 + std::max(0.0, t) + 12.0, 256);
    p.load -= beta * (near + far);
  }
  return p;
}

GwPoint dmt_gw_discrete(const std::vector<double>& heights, double t, double beta, double z0) {
  GwPoint p = discrete_gw(heights, t);
  p.load -= beta * p.count;
  if (z0 > 0.0) {
    double sum = 0.0;
    for (double z : heights)
      if (z <= t) sum += gap_attraction(t - z, z0);
    p.load -= beta * sum / static_cast<double>(heights.size());
  }
  return p;
}

double tangential_gw(double t, double slip) {
  if (slip < 0.0) throw std::invalid_argument("tangential_gw: slip must be >= 0");
  // An asperity slides once sqrt(w) slip >= w, i.e. w <= c = slip^2 (small asperities have small capacity).
  // Sliding ones: int_0^c w phi(t + w) dw = F_1(t) - [F_1(t + c) + c F_0(t + c)];
  // stuck ones:   slip int_c^inf sqrt(w) phi(t + w) dw = slip [F_1/2(t) - int_0^slip 2 s^2 phi(t + s^2) ds]  (w = s^2).
  const double c = slip * slip;
  const double sliding = gw_integral(1.0, t) - gw_integral(1.0, t + c) - c * gw_integral(0.0, t + c);
  const double head =
      slip > 0.0 ? gauss_legendre([t](double s) { return 2.0 * s * s * normal_pdf(t + s * s); }, 0.0, slip, 64) : 0.0;
  return sliding + slip * (gw_integral(0.5, t) - head);
}

double tangential_gw_discrete(const std::vector<double>& heights, double t, double slip) {
  double sum = 0.0;
  for (double z : heights) {
    const double w = z - t;
    if (w > 0.0) sum += std::min(std::sqrt(w) * slip, w);
  }
  return sum / static_cast<double>(heights.size());
}

double asperity_tabor(double beta, double z0) { return std::pow(2.0 * beta / (3.0 * M_PI), 2.0 / 3.0) / z0; }

}  // namespace tribex::gw
