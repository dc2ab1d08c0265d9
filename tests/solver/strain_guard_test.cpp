// SPDX-License-Identifier: MIT
// The small-strain guard's strain (solver/guards/strain_guard.hpp): the largest principal strain from the
// Cauchy stress of a linear elastic element, against strains built by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/guards/strain_guard.hpp"

namespace tribex::solver {
namespace {

// Voigt stress (xx yy zz xy yz zx) of strain eps (same order, tensor shear components) by Hooke's law.
void stress_of(const double eps[6], double lambda, double mu, double s[6]) {
  const double tr = eps[0] + eps[1] + eps[2];
  for (int i = 0; i < 3; ++i) s[i] = lambda * tr + 2.0 * mu * eps[i];
  for (int i = 3; i < 6; ++i) s[i] = 2.0 * mu * eps[i];
}

TEST(StrainGuard, LargestPrincipalStrainOfAxialAndShearStates) {
  const double lambda = 60e9, mu = 40e9;
  double s[6];
  const double axial[6] = {0.07, -0.02, -0.02, 0, 0, 0};
  stress_of(axial, lambda, mu, s);
  EXPECT_NEAR(largest_principal_strain(s, lambda, mu), 0.07, 1e-12);
  // Pure shear eps_xy = 0.03: principal strains +-0.03.
  const double shear[6] = {0, 0, 0, 0.03, 0, 0};
  stress_of(shear, lambda, mu, s);
  EXPECT_NEAR(largest_principal_strain(s, lambda, mu), 0.03, 1e-12);
  // Compression dominates: the magnitude counts.
  const double squeeze[6] = {-0.3, 0.1, 0.05, 0.0, 0.02, 0.0};
  stress_of(squeeze, lambda, mu, s);
  // The yz block [[0.1, 0.02], [0.02, 0.05]] has eigenvalues 0.075 +- sqrt(0.025^2 + 0.02^2); xx is -0.3.
  EXPECT_NEAR(largest_principal_strain(s, lambda, mu), 0.3, 1e-12);
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  EXPECT_EQ(largest_principal_strain(zero, lambda, mu), 0.0);
}

TEST(StrainGuard, RotatedStateHasTheSamePrincipalStrain) {
  // diag(0.04, 0.01, -0.02) rotated 30 degrees about z.
  const double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6), a = 0.04, b = 0.01;
  const double eps[6] = {a * c * c + b * sn * sn, a * sn * sn + b * c * c, -0.02, (a - b) * c * sn, 0, 0};
  const double lambda = 100e9, mu = 70e9;
  double s[6];
  stress_of(eps, lambda, mu, s);
  EXPECT_NEAR(largest_principal_strain(s, lambda, mu), 0.04, 1e-12);
}

}  // namespace
}  // namespace tribex::solver
