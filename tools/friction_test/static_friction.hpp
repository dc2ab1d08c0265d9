// SPDX-License-Identifier: MIT
// Static friction and adhesion from a clamp-voltage ramp (report Section 2.1.3, Eqs. 2.2-2.3).
//
// The nanotractor is walked out against a load spring of stiffness k, its leading clamp locked,
// and the clamp voltage stepped down while the position x is recorded. While friction holds, x
// stays put; when the friction capacity drops below the spring force the device slips back
// toward the spring's zero (a jump). For each jump between samples i and i+1:
//     F_s = k |x_i - x_zero|                                   (tangential spring force held)
//     F_N = F_c + m g - k_z z,  F_c = eps0 A V^2 / (2 g^2)     (Eq. 2.3, parallel-plate clamp,
//                                                               fringing neglected as in the report)
// with F_N the mean of the loads at samples i and i+1 (the slip happened between them; half
// their difference is reported as the load resolution). A straight line through (F_N, F_s),
//     F_s = mu_s F_N + mu_s F_adh                              (Eq. 2.2)
// gives mu_s (slope) and F_adh = intercept / slope, with uncertainties from the line's
// covariance (delta method for the ratio).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tools/common/least_squares.hpp"

namespace tribex::friction_test {

inline constexpr double vacuum_permittivity = 8.8541878128e-12;  // F/m
inline constexpr double standard_gravity = 9.80665;             // m/s^2

/// Clamp geometry and the terms of Eq. 2.3 other than F_c.
struct ClampLoad {
  double electrode_area = 0.0;  // m^2
  double gap = 0.0;             // m
  double mass = 0.0;            // kg (m g term)
  double kz = 0.0;              // N/m, out-of-plane suspension stiffness
  double z = 0.0;               // m, out-of-plane deflection (k_z z term)
  /// Eq. 2.3 at clamp voltage `volts`.
  double normal_force(double volts) const;
};

struct SlipEvent {
  std::size_t row = 0;          // the sample before the jump
  double position = 0.0;        // m, x_i
  double jump = 0.0;            // m, x_{i+1} - x_i
  double normal_force = 0.0;    // N, mean of F_N at i and i+1
  double load_resolution = 0.0; // N, half of |F_N(i) - F_N(i+1)|
  double friction_force = 0.0;  // N, k |x_i - x_zero|
};

/// Jumps larger than `min_jump` toward x_zero. `normal_force` is F_N per sample.
std::vector<SlipEvent> detect_slips(const std::vector<double>& position, const std::vector<double>& normal_force,
                                    double stiffness, double x_zero, double min_jump);

/// A friction load line F = a + b F_N = mu (F_N + F_adh) (Eq. 2.2 for the static test, F_d(F_N) of Fig. 2.11
/// for the dynamic one): the slope mu, the intercept a, F_adh = a / b, each with its 1-sigma (F_adh's by the
/// delta method, gradient (1/b, -a/b^2)), the intercept-slope correlation and the rms residual.
struct FrictionLine {
  double mu = 0.0, mu_sigma = 0.0;
  double intercept = 0.0, intercept_sigma = 0.0;            // N, mu F_adh
  double adhesion_force = 0.0, adhesion_force_sigma = 0.0;  // N
  double correlation = 0.0;                                 // between intercept and slope
  double rms_residual = 0.0;                                // N
};
/// The line's figures from its fitted parameters (a, b), their covariance c and the fit's rms residual.
FrictionLine friction_line(double a, double b, const Eigen::Matrix2d& c, double rms_residual);

struct StaticFit {
  std::vector<SlipEvent> events;
  FrictionLine line;  // mu = mu_s
};

/// Fits Eq. 2.2 to the slip events; throws tools::BadInput naming `what` when fewer than 3 are
/// found (no slip event at all gets its own message).
StaticFit fit_static(std::vector<SlipEvent> events, const std::string& what, double min_jump);

}  // namespace tribex::friction_test
