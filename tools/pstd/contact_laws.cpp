// SPDX-License-Identifier: MIT
#include "tools/pstd/contact_laws.hpp"

#include <cmath>
#include <numbers>

namespace tribex::pstd {

double effective_modulus(double e1, double nu1, double e2, double nu2) {
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

double line_contact_max_interference(double radius) { return 4.0 * radius * std::exp(-2.0); }

double line_contact_interference(double half_width, double radius) {
  if (half_width <= 0.0) return 0.0;
  return half_width * half_width / (4.0 * radius) * (2.0 * std::log(4.0 * radius / half_width) - 1.0);
}

double line_contact_half_width(double interference, double radius, bool* clamped) {
  if (clamped) *clamped = false;
  if (interference <= 0.0) return 0.0;
  // y = delta/(4R') = u^2 (-2 ln u - 1) with u = a/(4R') = e^-t, i.e. ln y = ln(2t-1) - 2t.
  const double log_y = std::log(interference / (4.0 * radius));
  if (log_y >= -2.0) {  // y >= e^-2: at or beyond the maximum of delta(a)
    if (clamped) *clamped = true;
    return 4.0 * radius / std::numbers::e;
  }
  const auto g = [log_y](double t) { return std::log(2.0 * t - 1.0) - 2.0 * t - log_y; };
  // Bracket: g(1) = -2 - ln y > 0; g(L+1) = ln(2L+1) - L - 2 < 0 for L = -ln y > 2.
  double lo = 1.0, hi = 1.0 - log_y;
  // Asymptotic start 2t - ln(2t) ~ L, good to a few per cent for small y.
  double t = 0.5 * (-log_y + std::log(-log_y));
  if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const double gt = g(t);
    if (gt > 0.0) lo = t; else hi = t;
    if (gt == 0.0) break;
    const double slope = 2.0 / (2.0 * t - 1.0) - 2.0;  // g'(t) < 0 for t > 1
    double next = t - gt / slope;
    if (!(next > lo && next < hi) || slope == 0.0) next = 0.5 * (lo + hi);
    if (std::abs(next - t) <= 1e-16 * t) { t = next; break; }
    t = next;
  }
  return 4.0 * radius * std::exp(-t);
}

double line_contact_load(double half_width, double radius, double modulus) {
  return std::numbers::pi * half_width * half_width * modulus / (4.0 * radius);
}

double line_contact_stiffness(double half_width, double radius, double modulus) {
  if (half_width <= 0.0) return 0.0;
  const double denom = std::log(4.0 * radius / half_width) - 1.0;  // -> 0 at the clamp a = 4R'/e
  return denom > 0.0 ? std::numbers::pi * modulus / (2.0 * denom) : 0.0;
}

double hertz_half_width(double interference, double radius) {
  return interference > 0.0 ? std::sqrt(interference * radius) : 0.0;
}

double hertz_load(double interference, double radius, double modulus) {
  return interference > 0.0 ? 4.0 / 3.0 * modulus * std::sqrt(interference * interference * interference * radius)
                            : 0.0;
}

double hertz_stiffness(double interference, double radius, double modulus) {
  return 2.0 * modulus * hertz_half_width(interference, radius);
}

}  // namespace tribex::pstd
