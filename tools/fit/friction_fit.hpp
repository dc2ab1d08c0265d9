// SPDX-License-Identifier: MIT
// Nonlinear least-squares fit of a FrictionModel to friction-vs-load data (tools/common
// Levenberg-Marquardt: covariance s^2 (J^T J)^-1 and correlation), the DMT straight-line
// shortcut of docs/theory.md 9.2, and synthetic data with known parameters for the tests.
#pragma once

#include <cstdint>
#include <vector>

#include "tools/common/least_squares.hpp"
#include "tools/fit/friction_model.hpp"

namespace tribex::fit {

/// absolute: r_i = F_model - F_i (noise of constant size, the usual lateral-signal noise);
/// relative: r_i = ln(F_model/F_i) (noise proportional to F; needs F_i > 0).
enum class Residual { absolute, relative };

struct FrictionFit {
  FrictionParams best;
  tools::FitResult lm;              // parameters in FrictionModel::free_names() order
  std::vector<std::string> names;
  double pull_off_load = 0;         // of the fitted model
  /// Returns sigma of the named parameter (0 when it was not fitted).
  double sigma(const std::string& name) const;
  double correlation(const std::string& a, const std::string& b) const;
};

/// Fits from automatic starting values (W from the most negative load, tau by linear least
/// squares at that W; three W starts, the best kept). Throws solver::NumericalFailure when no
/// start converges to a non-degenerate fit.
FrictionFit fit_friction(const FrictionModel& model, const std::vector<double>& load,
                         const std::vector<double>& friction, Residual residual = Residual::absolute);

/// tau/Ec^k with its sigma from the covariance (first-order propagation including the tau-Ec
/// covariance). Report 3.3: with Ec free, Eq. 3.1 determines only tau/Ec^(2/3) when A and b do
/// not depend on Ec and b = 0; with b != 0 the factor (P/(Ebar_c h_c^2))^b shifts the exponent
/// to about 2/3 + b, which valley_exponent() measures.
struct Combination {
  double exponent = 0, value = 0, sigma = 0;
};
Combination tau_over_ec_power(const FrictionFit& fit, double exponent);
/// The exponent k of the best-determined combination tau/Ec^k: the slope of the fit's valley,
/// k = cov(ln tau, ln Ec)/var(ln Ec), whose combination has sigma_ln = sigma_ln_tau sqrt(1 - rho^2).
/// Needs a fit with Ec free.
Combination tau_over_ec_valley(const FrictionFit& fit);

/// DMT shortcut (docs/theory.md 9.2): F^(3/2) = tau^(3/2) pi^(3/2) (3R/(4E*)) (L + 2 pi W R) is a
/// straight line in L; its L-intercept gives W and its slope s gives tau = (4E* s/(3R))^(2/3)/pi.
/// Uses the points with F > 0; sigmas from the line fit's covariance.
struct ShortcutFit {
  double tau = 0, work_of_adhesion = 0, tau_sigma = 0, work_sigma = 0;
};
ShortcutFit dmt_shortcut(const std::vector<double>& load, const std::vector<double>& friction, double radius,
                         double reduced_modulus);

/// Synthetic friction at `loads` from the model with parameters `p`, plus seeded Gaussian noise:
/// sigma = relative_noise * F (relative) or relative_noise * max F (absolute).
std::vector<double> synth_friction(const FrictionModel& model, const FrictionParams& p,
                                   const std::vector<double>& loads, double relative_noise, Residual kind,
                                   std::uint64_t seed);

/// `n` loads evenly spaced from `from` to `to`.
std::vector<double> load_ramp(double from, double to, int n);

}  // namespace tribex::fit
