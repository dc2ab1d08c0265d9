// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tools/common/least_squares.hpp"

namespace tribex::tools {
namespace {

TEST(LeastSquares, LineThroughExactPointsHasZeroResidual) {
  const FitResult f = fit_line({1e-6, 2e-6, 3e-6, 4e-6}, {0.5e-6 + 0.3e-6, 0.5e-6 + 0.6e-6, 0.5e-6 + 0.9e-6, 0.5e-6 + 1.2e-6});
  EXPECT_NEAR(f.parameters(0), 0.5e-6, 1e-18);
  EXPECT_NEAR(f.parameters(1), 0.3, 1e-12);
  EXPECT_LT(f.rms_residual, 1e-18);
}

// For a model linear in its parameters, LM's covariance s^2 (J^T J)^-1 must equal the ordinary
// least-squares covariance of fit_line, and both fits must agree.
TEST(LeastSquares, LevenbergMarquardtMatchesLinearRegressionOnALine) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<double> x, y;
  for (int i = 0; i < 40; ++i) {
    x.push_back(0.1 * i);
    y.push_back(2.0 - 0.7 * x.back() + noise(rng));
  }
  const FitResult line = fit_line(x, y);
  auto residuals = [&](const Eigen::VectorXd& p) -> std::optional<Eigen::VectorXd> {
    Eigen::VectorXd r(static_cast<Eigen::Index>(x.size()));
    for (std::size_t i = 0; i < x.size(); ++i) r(static_cast<Eigen::Index>(i)) = p(0) + p(1) * x[i] - y[i];
    return r;
  };
  const FitResult lm = levenberg_marquardt(residuals, Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, 1.0));
  EXPECT_TRUE(lm.converged);
  EXPECT_NEAR(lm.parameters(0), line.parameters(0), 1e-7);
  EXPECT_NEAR(lm.parameters(1), line.parameters(1), 1e-7);
  EXPECT_NEAR(lm.sigma(0), line.sigma(0), 1e-6 * line.sigma(0));
  EXPECT_NEAR(lm.sigma(1), line.sigma(1), 1e-6 * line.sigma(1));
  EXPECT_NEAR(lm.correlation(0, 1), line.correlation(0, 1), 1e-6);
  EXPECT_LT(lm.correlation(0, 1), -0.5);  // intercept and slope of x in [0, 4] anticorrelate
  EXPECT_NEAR(lm.residual_sigma, 0.05, 0.015);
}

TEST(LeastSquares, RecoversAnExponentialDecayWithScaledParameters) {
  std::vector<double> t, y;
  for (int i = 0; i < 50; ++i) {
    t.push_back(1e-4 * i);
    y.push_back(3e-9 * std::exp(-2000.0 * t.back()));
  }
  auto residuals = [&](const Eigen::VectorXd& p) -> std::optional<Eigen::VectorXd> {
    if (p(1) <= 0) return std::nullopt;
    Eigen::VectorXd r(50);
    for (int i = 0; i < 50; ++i) r(i) = p(0) * std::exp(-p(1) * t[static_cast<std::size_t>(i)]) - y[static_cast<std::size_t>(i)];
    return r;
  };
  const FitResult f = levenberg_marquardt(residuals, Eigen::Vector2d(1e-9, 500.0), Eigen::Vector2d(1e-9, 1000.0));
  EXPECT_NEAR(f.parameters(0), 3e-9, 1e-15);
  EXPECT_NEAR(f.parameters(1), 2000.0, 1e-4);
}

}  // namespace
}  // namespace tribex::tools
