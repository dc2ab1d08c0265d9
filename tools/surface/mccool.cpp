// SPDX-License-Identifier: MIT
#include "tools/surface/mccool.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/rough/gw_integrals.hpp"

namespace tribex::surface {

double composite_modulus(double e1, double nu1, double e2, double nu2) {
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

McCoolResult mccool_at_separation(const McCoolInput& in, double t) {
  McCoolResult r;
  r.summits = summit_statistics(in.moments);
  r.t = t;
  const auto& s = r.summits;
  const double f0 = gw::gw_integral(0.0, t), f1 = gw::gw_integral(1.0, t), f32 = gw::gw_integral(1.5, t);
  r.contacts = s.density * in.apparent_area * f0;
  r.area_ratio = M_PI * s.density * s.radius * s.sigma_s * f1;
  r.true_area = r.area_ratio * in.apparent_area;
  r.load = (4.0 / 3.0) * s.density * in.e_star * std::sqrt(s.radius) * std::pow(s.sigma_s, 1.5) * f32 * in.apparent_area;
  r.mean_pressure = r.true_area > 0.0 ? r.load / r.true_area : 0.0;
  const double w_h = s.radius * std::pow(3.0 * M_PI * in.hardness / (4.0 * in.e_star), 2);
  r.fraction_past_hardness = f0 > 0.0 ? gw::gw_integral(0.0, t + w_h / s.sigma_s) / f0 : 0.0;
  // McCool's closed forms with the exact constants sqrt(3 pi)/48 and pi^{-3/4}/(9 sqrt 2).
  const double am = s.alpha - 0.8968;
  r.area_ratio_closed_form = std::sqrt(3.0 * M_PI) / 48.0 * std::sqrt(am) * f1;
  r.load_closed_form = std::pow(M_PI, -0.75) / (9.0 * std::sqrt(2.0)) * in.e_star * std::sqrt(in.moments.m2) *
                       std::pow(am, 0.75) * f32 * in.apparent_area;
  return r;
}

McCoolResult mccool_at_load(const McCoolInput& in, double load) {
  double lo = -3.0, hi = 8.0;
  const double p_lo = mccool_at_separation(in, lo).load, p_hi = mccool_at_separation(in, hi).load;
  if (!(load <= p_lo && load >= p_hi))
    throw std::domain_error("load " + std::to_string(load) + " N lies outside the range " + std::to_string(p_hi) + " to " +
                            std::to_string(p_lo) + " N covered by d/sigma_s in [-3, 8]");
  for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mccool_at_separation(in, mid).load > load) lo = mid; else hi = mid;
  }
  return mccool_at_separation(in, 0.5 * (lo + hi));
}

}  // namespace tribex::surface
