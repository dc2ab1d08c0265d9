// SPDX-License-Identifier: MIT
#include "contact/rough/gw_integrals.hpp"

#include "contact/rough/gauss_legendre.hpp"

#include <cmath>
#include <stdexcept>

namespace tribex::gw {
namespace {

constexpr int gl_order = 20;

// The 20-point rule on [-1, 1], built once.
const QuadratureRule& rule() {
  static const QuadratureRule r = gauss_legendre_rule(gl_order, -1.0, 1.0);
  return r;
}

}  // namespace

double normal_pdf(double t) { return std::exp(-0.5 * t * t) / std::sqrt(2.0 * M_PI); }

double normal_upper_tail(double t) { return 0.5 * std::erfc(t / std::sqrt(2.0)); }

double normal_quantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::domain_error("normal_quantile: p must lie in (0, 1)");
  double lo = -40.0, hi = 40.0;  // Q(x) = 1 - p is decreasing in x
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::fabs(lo)); ++i) {
    const double mid = 0.5 * (lo + hi);
    if (normal_upper_tail(mid) > 1.0 - p) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

double gauss_legendre(const std::function<double(double)>& f, double a, double b, int panels) {
  const auto& r = rule();
  const double h = (b - a) / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double c = a + (p + 0.5) * h;
    for (int i = 0; i < gl_order; ++i)
      sum += r.w[static_cast<std::size_t>(i)] * f(c + 0.5 * h * r.x[static_cast<std::size_t>(i)]);
  }
  return 0.5 * h * sum;
}

double gw_integral_quadrature(double n, double t) {
  if (n < 0.0) throw std::domain_error("gw_integral: n must be >= 0");
  // u = s^2: int_0^inf u^n e^{-t u - u^2/2} du = int_0^inf 2 s^{2n+1} e^{-t s^2 - s^4/2} ds.
  // Cut where the exponent t s^2 + s^4/2 reaches 80 (e^-80 ~ 1e-35: far below 1e-14 of the peak,
  // whose exponent is at most t^2/2 = 4.5 for t >= -3).
  const double s2 = -t + std::sqrt(t * t + 160.0);
  const double s_max = std::sqrt(s2) * 1.05;
  auto g = [n, t](double s) {
    const double u = s * s;
    return 2.0 * std::pow(s, 2.0 * n + 1.0) * std::exp(-t * u - 0.5 * u * u);
  };
  // Resolve the peak region, whose width scales like min(1, 1/sqrt|t|): 64 panels are plenty.
  return normal_pdf(t) * gauss_legendre(g, 0.0, s_max, 64);
}

double gw_integral(double n, double t) {
  if (n == 0.0) return normal_upper_tail(t);
  if (n == 1.0) return normal_pdf(t) - t * normal_upper_tail(t);
  return gw_integral_quadrature(n, t);
}

}  // namespace tribex::gw
