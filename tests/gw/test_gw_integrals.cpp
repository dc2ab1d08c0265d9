// SPDX-License-Identifier: MIT
// F_n(t) against closed forms, an independent quadrature and the published values of docs/theory.md 10.3.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/rough/gw_integrals.hpp"

using namespace tribex::gw;

namespace {
/// Independent check: double-exponential (exp-sinh) quadrature of the original form
/// F_n(t) = int_0^inf u^n phi(u + t) du with u = exp(pi/2 sinh tau), trapezoid in tau.
/// Different variable, rule and cut-off from the library's Gauss-Legendre in s = sqrt(u).
double fn_exp_sinh(double n, double t) {
  const double h = 1.0 / 256.0;
  double sum = 0.0;
  for (int k = -6 * 256; k <= 6 * 256; ++k) {
    const double tau = k * h;
    const double u = std::exp(0.5 * M_PI * std::sinh(tau));
    const double du = u * 0.5 * M_PI * std::cosh(tau);
    const double phi = std::exp(-0.5 * (u + t) * (u + t)) / std::sqrt(2.0 * M_PI);
    sum += std::pow(u, n) * phi * du;
  }
  return h * sum;
}
}  // namespace

TEST(GwIntegrals, QuadratureMatchesClosedFormsForN0AndN1To1e10) {
  double worst = 0.0;
  for (int i = 0; i <= 110; ++i) {
    const double t = -3.0 + 0.1 * i;
    const double e0 = std::fabs(gw_integral_quadrature(0.0, t) / (0.5 * std::erfc(t / std::sqrt(2.0))) - 1.0);
    const double f1 = std::exp(-0.5 * t * t) / std::sqrt(2 * M_PI) - t * 0.5 * std::erfc(t / std::sqrt(2.0));
    const double e1 = std::fabs(gw_integral_quadrature(1.0, t) / f1 - 1.0);
    worst = std::max({worst, e0, e1});
  }
  std::printf("  F_0, F_1 quadrature vs closed form on [-3, 8]: worst relative error %.2e\n", worst);
  EXPECT_LT(worst, 1e-10) << "worst relative error " << worst;
}

TEST(GwIntegrals, AgreesWithAnIndependentQuadratureTo1e10ForHalfIntegers) {
  double worst = 0.0;
  for (double n : {0.0, 0.5, 1.0, 1.5}) {
    for (int i = 0; i <= 44; ++i) {
      const double t = -3.0 + 0.25 * i;
      worst = std::max(worst, std::fabs(gw_integral(n, t) / fn_exp_sinh(n, t) - 1.0));
    }
  }
  std::printf("  F_n vs exp-sinh quadrature, n = 0, 1/2, 1, 3/2 on [-3, 8]: worst relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-10) << "worst relative difference " << worst;
}

TEST(GwIntegrals, PublishedValues) {
  // docs/theory.md 10.3, given to 5 significant digits: tolerance is half a unit of the last digit.
  EXPECT_NEAR(gw_integral(0, 0), 0.5, 1e-15);
  EXPECT_NEAR(gw_integral(1, 0), 0.39894, 0.5e-5);
  EXPECT_NEAR(gw_integral(1.5, 0), 0.43002, 0.5e-5);
  EXPECT_NEAR(gw_integral(1, 1), 0.083315, 0.5e-6);
  EXPECT_NEAR(gw_integral(1.5, 1), 0.075668, 0.5e-6);
  EXPECT_NEAR(gw_integral(1, 2), 0.008491, 0.5e-6);
  EXPECT_NEAR(gw_integral(1.5, 2), 0.006648, 0.5e-6);
  // Exact identities: F_1/2(0) = Gamma(3/4) 2^{-1/4} / (2 sqrt(pi)) ... via int_0^inf u^n phi(u) du = 2^{n/2} Gamma((n+1)/2) / (2 sqrt(pi)).
  for (double n : {0.5, 1.5}) {
    const double exact = std::pow(2.0, n / 2) * std::tgamma((n + 1) / 2) / (2 * std::sqrt(M_PI));
    EXPECT_NEAR(gw_integral(n, 0) / exact, 1.0, 1e-12);
  }
}

TEST(GwIntegrals, NormalQuantileInvertsTheTail) {
  for (double p : {1e-6, 0.01, 0.3, 0.5, 0.77, 0.999999}) {
    const double x = normal_quantile(p);
    EXPECT_NEAR(1.0 - normal_upper_tail(x), p, 1e-14 + 1e-12 * p);
  }
}
