// SPDX-License-Identifier: MIT
#include "tools/fit/maugis_dugdale.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tribex::fit {
namespace {

// Left side of MD Eq. (1) minus 1.
double eq1(double a, double m, double lambda) {
  const double s = std::sqrt(std::max(m * m - 1.0, 0.0));
  const double t = std::atan(s);
  return 0.5 * lambda * a * a * (s + (m * m - 2.0) * t) + (4.0 / 3.0) * lambda * lambda * a * (s * t - m + 1.0) -
         1.0;
}

// Root of an increasing f on [lo, hi] with f(lo) < 0 < f(hi): the Illinois variant of regula falsi
// (superlinear, and it keeps the bracket, so it cannot leave the stable branch).
template <class F>
double bracketed_root(F&& f, double lo, double hi, double rel_tol) {
  double f_lo = f(lo), f_hi = f(hi);
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > rel_tol * hi; ++it) {
    double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (fx == 0.0) return x;
    if (fx < 0) {
      lo = x, f_lo = fx;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = x, f_hi = fx;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
    if (std::abs(fx) < 1e-15) break;
  }
  return std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
}

}  // namespace

double MaugisPoint::carried_bar(double lambda) const {
  return p_bar + 0.5 * std::numbers::pi * lambda * a_bar * a_bar * (m * m - 1.0);
}

MaugisDugdale::MaugisDugdale(double lambda) : lambda_(lambda) {
  if (!(lambda > 0) || !std::isfinite(lambda)) throw std::invalid_argument("Maugis-Dugdale: lambda must be > 0");
  // Golden-section search for the minimum of P_bar(a_bar); P_bar is unimodal (it falls from 0 at
  // a_bar = 0 to the pull-off and then rises like a_bar^3). The bracket [1e-6, 4] holds every
  // lambda: the pull-off radius lies between the JKR value 0.63*6^(1/3) = 1.15 and 0.
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 1e-6, hi = 4.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = at_radius(x1).p_bar, f2 = at_radius(x2).p_bar;
  for (int it = 0; it < 200 && hi - lo > 1e-12; ++it) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = at_radius(x1).p_bar;
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = at_radius(x2).p_bar;
    }
  }
  pull_off_ = at_radius(0.5 * (lo + hi));
}

MaugisPoint MaugisDugdale::at_radius(double a_bar) const {
  MaugisPoint p;
  p.a_bar = a_bar;
  double lo = 1.0, hi = 2.0;
  while (eq1(a_bar, hi, lambda_) < 0.0) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e12) throw std::runtime_error("Maugis-Dugdale: no Dugdale-zone size m solves Eq. (1)");
  }
  p.m = bracketed_root([&](double m) { return eq1(a_bar, m, lambda_); }, lo, hi, 1e-14);
  const double s = std::sqrt(p.m * p.m - 1.0);
  p.p_bar = a_bar * a_bar * a_bar - lambda_ * a_bar * a_bar * (s + p.m * p.m * std::atan(s));
  return p;
}

MaugisPoint MaugisDugdale::at_load(double p_bar) const {
  if (p_bar < pull_off_.p_bar) throw std::domain_error("Maugis-Dugdale: load below the pull-off load");
  double lo = pull_off_.a_bar, hi = std::max(2.0, lo * 2.0);
  while (at_radius(hi).p_bar < p_bar) {
    lo = hi;
    hi *= 2.0;
  }
  // P_bar rises monotonically on the stable branch.
  if (p_bar == pull_off_.p_bar) return pull_off_;
  return at_radius(bracketed_root([&](double a) { return at_radius(a).p_bar - p_bar; }, lo, hi, 1e-13));
}

}  // namespace tribex::fit
