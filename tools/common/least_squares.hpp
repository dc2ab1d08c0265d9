// SPDX-License-Identifier: MIT
// Small least-squares fitters shared by the data-reduction tools (friction-test, fit).
//
// levenberg_marquardt(): minimises S(p) = sum_i r_i(p)^2 with a forward-difference Jacobian,
// Marquardt's diagonal scaling (J^T J + lambda diag(J^T J)) dp = -J^T r, and lambda /10 on
// success, x10 on failure. Parameters are handled as p = scale .* q so that quantities of very
// different size (nN forces next to um positions) are equally conditioned. The covariance is
// the usual asymptotic one, C = s^2 (J^T J)^-1 with s^2 = S / (n - p) the residual variance
// (Press et al., Numerical Recipes, 15.5-15.6), and the correlation matrix C_ij / sqrt(C_ii C_jj).
//
// fit_line(): ordinary least squares y = a + b x with the same covariance rule.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Dense>

namespace tribex::tools {

struct FitResult {
  Eigen::VectorXd parameters;
  Eigen::MatrixXd covariance;   // s^2 (J^T J)^-1
  Eigen::MatrixXd correlation;
  double rms_residual = 0.0;    // sqrt(S / n)
  double residual_sigma = 0.0;  // sqrt(S / (n - p)), the estimate of the noise level
  int iterations = 0;
  bool converged = false;
  double sigma(int i) const { return std::sqrt(covariance(i, i)); }
};

/// Residuals of a model at parameters p; nullopt when p is outside the model's domain (the
/// step is then rejected like an uphill one).
using ResidualFunction = std::function<std::optional<Eigen::VectorXd>(const Eigen::VectorXd& p)>;

struct LmOptions {
  int max_iterations = 200;
  double relative_tolerance = 1e-10;  // stop when S decreases by less than this fraction
  /// Held fixed where true (not fitted; zero variance).
  std::vector<bool> fixed;
};

/// Fits from `start` with per-parameter `scale` (typical magnitudes, > 0). Throws
/// std::runtime_error when the start point is outside the model's domain or J^T J is singular.
FitResult levenberg_marquardt(const ResidualFunction& residuals, Eigen::VectorXd start,
                              const Eigen::VectorXd& scale, const LmOptions& options = {});

/// y = a + b x by ordinary least squares; parameters (a, b). Needs at least 3 points.
FitResult fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace tribex::tools
