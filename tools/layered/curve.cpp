// SPDX-License-Identifier: MIT
#include "tools/layered/curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tools/common/errors.hpp"

namespace tribex::layered {
namespace {

double hertz_radius(const Contact& c, double load, double sphere_radius) {
  return std::cbrt(3.0 * load * sphere_radius / (4.0 * c.effective_modulus()));
}

CurvePoint point_of(Contact& contact, const SphereSolution& s, double scale, double sphere_radius) {
  CurvePoint p;
  p.load = s.load;
  p.p_tilde = s.load / scale;
  p.radius = s.radius;
  p.approach = s.approach;
  p.f = std::pow(s.radius / hertz_radius(contact, s.load, sphere_radius), 2);
  p.center_pressure = contact.pressure(s, {0.0})[0];
  return p;
}

}  // namespace

std::vector<double> p_tilde_list(Contact& contact, double scale, double lo, double hi, int points, Spacing spacing) {
  if (!(lo > 0) || !(hi >= lo)) throw tools::BadInput("P~ range: need 0 < LO <= HI (e.g. --p-tilde 0.02,1.59)");
  if (points < 1 || (points == 1 && hi > lo)) throw tools::BadInput("--points must be >= 2 for a range (or give LO = HI)");
  std::vector<double> out;
  if (spacing == Spacing::approach && points > 1) {
    const double r = contact.sphere_radius();
    const auto s_lo = contact.sphere_at_load(lo * scale, hertz_radius(contact, lo * scale, r));
    const auto s_hi = contact.sphere_at_load(hi * scale, hertz_radius(contact, hi * scale, r));
    double guess = s_lo.radius;
    for (int i = 0; i < points; ++i) {
      const double d = s_lo.approach + (s_hi.approach - s_lo.approach) * i / (points - 1.0);
      const auto s = contact.sphere_at_approach(d, guess);
      guess = s.radius;
      out.push_back(s.load / scale);
    }
    out.front() = lo;  // exact ends (the root finder's 1e-14)
    out.back() = hi;
    return out;
  }
  for (int i = 0; i < points; ++i) {
    const double t = points == 1 ? 0.0 : i / (points - 1.0);
    out.push_back(spacing == Spacing::log ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t);
  }
  return out;
}

std::vector<CurvePoint> load_curve(Contact& contact, double scale, const std::vector<double>& p_tilde) {
  std::vector<double> sorted = p_tilde;
  std::sort(sorted.begin(), sorted.end());
  std::vector<CurvePoint> out;
  double guess = 0.0, last = 0.0;
  for (double pt : sorted) {
    if (!(pt > 0)) throw tools::BadInput("loads must be > 0 (a P~ or load of " + std::to_string(pt) + " was given)");
    const double load = pt * scale;
    // First guess: Hertz on the top layer; then the previous radius scaled as P^(1/3).
    guess = out.empty() ? hertz_radius(contact, load, contact.sphere_radius()) : guess * std::cbrt(load / last);
    const SphereSolution s = contact.sphere_at_load(load, guess);
    out.push_back(point_of(contact, s, scale, contact.sphere_radius()));
    guess = s.radius;
    last = s.load;
  }
  return out;
}

PowerFit power_fit(const std::vector<CurvePoint>& points, double lo, double hi) {
  std::vector<double> x, y, f;
  for (const auto& p : points) {
    if (p.p_tilde < lo * (1 - 1e-12) || p.p_tilde > hi * (1 + 1e-12)) continue;
    x.push_back(std::log(p.p_tilde));
    y.push_back(std::log(p.f));
    f.push_back(p.f);
  }
  PowerFit fit;
  const std::size_t n = x.size();
  fit.rows = static_cast<int>(n);
  if (n < 3) return fit;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  fit.b = sxy / sxx;
  const double ln_a = my - fit.b * mx;
  fit.A = std::exp(ln_a);
  double ss = 0, fm = 0, ss_res = 0, ss_tot = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - ln_a - fit.b * x[i];
    ss += r * r;
    fm += f[i] / n;
  }
  for (std::size_t i = 0; i < n; ++i) {
    ss_res += std::pow(f[i] - fit.A * std::exp(fit.b * x[i]), 2);
    ss_tot += std::pow(f[i] - fm, 2);
  }
  const double s2 = ss / (n - 2.0);
  fit.b_se = std::sqrt(s2 / sxx);
  fit.A_se = fit.A * std::sqrt(s2 * (1.0 / n + mx * mx / sxx));
  fit.r2 = ss_tot > 0 ? 1.0 - ss_res / ss_tot : std::nan("");
  fit.rms = std::sqrt(ss / n);
  fit.lo = std::exp(*std::min_element(x.begin(), x.end()));
  fit.hi = std::exp(*std::max_element(x.begin(), x.end()));
  return fit;
}

}  // namespace tribex::layered
