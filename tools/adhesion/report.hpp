// SPDX-License-Identifier: MIT
// The files of `tribex adhesion-curve` (README.md): the traced curve as CSV, the analytic neighbours
// (DMT, JKR, Maugis-Dugdale at lambda = 1.157 mu_T) as CSV, and the JSON summary.
#pragma once

#include <string>

#include "tools/adhesion/curve.hpp"

namespace tribex::adhesion {

/// The normalisations of docs/theory.md 8.4 with the captured work W_c (docs/theory.md 6.7.6).
struct Scales {
  double work = 0;    // W_c, J/m^2
  double load = 0;    // pi W_c R, N
  double radius = 0;  // (pi W_c R^2/K)^(1/3), m
  double approach = 0;// (pi^2 W_c^2 R/K^2)^(1/3), m
  double tabor = 0;   // mu_T = (R W^2/(E*^2 z0^3))^(1/3) with the nominal W
  double lambda = 0;  // Maugis lambda = 2 sigma0 (R/(pi W_c K^2))^(1/3), sigma0 = 16 W/(9 sqrt 3 z0)
};
Scales scales_of(const Problem& pb);

std::string curve_csv(const Curve& c, const Problem& pb, const std::string& about);
/// DMT, JKR and MD load and approach against a_bar (0.02..max_a_bar), normalised.
std::string limits_csv(const Scales& s, double max_a_bar);
std::string summary_json(const Curve& c, const Problem& pb, double seconds);

}  // namespace tribex::adhesion
