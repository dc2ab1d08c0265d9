// SPDX-License-Identifier: MIT
// McCool's Greenwood-Williamson predictions for two rough surfaces in contact (report Eqs. 4.6-4.9,
// Table 4.2; docs/theory.md 10.3). With the summit statistics of the combined moments, t = d / sigma_s:
//   N    = eta A0 F_0(t)                                      number of contacts
//   Ac/A0 = pi eta R_s sigma_s F_1(t)  = 0.0640 (alpha - 0.8968)^{1/2} F_1(t)                  (4.6)
//   P/A0  = (4/3) eta E* R_s^{1/2} sigma_s^{3/2} F_{3/2}(t)
//         = 0.0333 E* m2^{1/2} (alpha - 0.8968)^{3/4} F_{3/2}(t)                               (4.7)
//   E* = ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)^{-1}                                               (4.8)
// Fraction past the hardness H: the Hertz mean pressure (4 E*/(3 pi)) sqrt(w/R) exceeds H when
// w > w_H = R (3 pi H / (4 E*))^2, so among the contacting asperities the fraction is F_0(t + w_H/sigma_s)/F_0(t).
#pragma once

#include "tools/surface/spectral_moments.hpp"

namespace tribex::surface {

double composite_modulus(double e1, double nu1, double e2, double nu2);

struct McCoolInput {
  Moments moments;              // combined moments of the two surfaces
  double e_star = 0.0;          // Pa
  double hardness = 11e9;       // Pa (polysilicon, report ref. 4.2)
  double apparent_area = 1e-9;  // m^2 (10 x 100 um^2)
};

struct McCoolResult {
  SummitStatistics summits;
  double t = 0.0;                   // d / sigma_s
  double contacts = 0.0;            // number of contacting asperities on A0
  double area_ratio = 0.0;          // Ac / A0
  double true_area = 0.0;           // m^2
  double load = 0.0;                // N
  double mean_pressure = 0.0;       // P / Ac, Pa
  double fraction_past_hardness = 0.0;  // of the contacting asperities
  double area_ratio_closed_form = 0.0;  // McCool's 0.0640 form (check)
  double load_closed_form = 0.0;        // McCool's 0.0333 form (check), N
};

McCoolResult mccool_at_separation(const McCoolInput& in, double t);
/// Solves P(t) = load for t by bisection on [-3, 8] (P decreases with t); throws std::domain_error outside.
McCoolResult mccool_at_load(const McCoolInput& in, double load);

}  // namespace tribex::surface
