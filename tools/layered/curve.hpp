// SPDX-License-Identifier: MIT
// A load curve of the layered contact in the coated study's variables (verification/coated/README.md,
// report Eqs. B.1-B.2): P~ = P/(E*_top h_top^2), f = pi a^2 / [pi (3 P R/(4 E_eff))^(2/3)] with
// 1/E_eff = 1/E*_indenter + 1/E*_top, and the power law f = A P~^b fitted by least squares on
// ln f = ln A + b ln P~ (equal weight per load, as verification/coated/study.py).
#pragma once

#include <string>
#include <vector>

#include "tools/layered/contact.hpp"

namespace tribex::layered {

struct CurvePoint {
  double p_tilde = 0, load = 0, radius = 0, approach = 0, f = 0, center_pressure = 0;
};

enum class Spacing { log, linear, approach };

/// The P~ values of `points` loads from lo to hi: log-spaced, linear in P~, or (approach) linear in
/// the approach delta, which needs the contact (`contact`) to find delta at both ends.
std::vector<double> p_tilde_list(Contact& contact, double scale, double lo, double hi, int points, Spacing spacing);

/// One solution per P~ (ascending); `scale` = E*_top h_top^2 (N), so P = scale P~.
std::vector<CurvePoint> load_curve(Contact& contact, double scale, const std::vector<double>& p_tilde);

struct PowerFit {
  double A = 0, b = 0, A_se = 0, b_se = 0, r2 = 0, rms = 0, lo = 0, hi = 0;
  int rows = 0;
};

/// Least squares of ln f = ln A + b ln P~ over the points with lo <= P~ <= hi (study.py's power_fit:
/// standard errors of the regression; R^2 of f itself; rms of ln f about the fit).
PowerFit power_fit(const std::vector<CurvePoint>& points, double lo, double hi);

}  // namespace tribex::layered
