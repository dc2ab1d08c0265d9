// SPDX-License-Identifier: MIT
// The single-asperity laws of the PSTD model: eq. (2.5) inverted and re-evaluated, its small-a and
// large-a limits, and eq. (2.6) against the classical Hertz relations (Johnson, Contact Mechanics, 4.22-4.23).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tools/pstd/contact_laws.hpp"

using namespace tribex::pstd;

TEST(PstdLineContact, InterferenceRoundTripsThroughTheInverse) {
  for (double radius : {5e-9, 1e-7, 1e-5}) {
    const double dmax = line_contact_max_interference(radius);
    for (double f = 1e-12; f < 1.0; f *= 1.7) {
      const double delta = f * 0.999999 * dmax;
      bool clamped = true;
      const double a = line_contact_half_width(delta, radius, &clamped);
      EXPECT_FALSE(clamped);
      EXPECT_NEAR(line_contact_interference(a, radius) / delta, 1.0, 1e-12) << "R=" << radius << " f=" << f;
    }
  }
}

TEST(PstdLineContact, HalfWidthRoundTripsWhereWellConditioned) {
  // a -> delta -> a; for a <= 2R'/e the inverse has condition number |dln a/dln delta| <= 1 (1/2 as a -> 0).
  const double radius = 1e-7;
  for (double u = 1e-9; u <= 2.0 / std::numbers::e; u *= 1.3) {
    const double a = 4.0 * radius * u / 2.0;
    EXPECT_NEAR(line_contact_half_width(line_contact_interference(a, radius), radius) / a, 1.0, 1e-12) << u;
  }
}

TEST(PstdLineContact, SmallHalfWidthLimit) {
  // a -> 0: delta ~ (a^2/(2R')) ln(4R'/a), i.e. a^2 ln(4R'/a)/(2R' delta) -> 1 with error 1/(2 ln(4R'/a) - 1),
  // and the contact stiffness dP/d(delta) = pi E'/(2(ln(4R'/a) - 1)) vanishes logarithmically.
  const double radius = 1e-7, modulus = 85e9;
  double previous_error = 1.0;
  for (double delta = 1e-12; delta > 1e-40; delta *= 1e-4) {
    const double a = line_contact_half_width(delta, radius);
    const double log_term = std::log(4.0 * radius / a);
    const double ratio = a * a * log_term / (2.0 * radius * delta);
    EXPECT_NEAR(ratio, 1.0, 1.0 / (2.0 * log_term - 1.0) * (1.0 + 1e-9));
    EXPECT_LT(std::abs(ratio - 1.0), previous_error);
    previous_error = std::abs(ratio - 1.0);
    // Stiffness against a centred finite difference of P(delta) through the inverse.
    const double h = 1e-4 * delta;
    const double p_plus = line_contact_load(line_contact_half_width(delta + h, radius), radius, modulus);
    const double p_minus = line_contact_load(line_contact_half_width(delta - h, radius), radius, modulus);
    EXPECT_NEAR((p_plus - p_minus) / (2.0 * h) / line_contact_stiffness(a, radius, modulus), 1.0, 1e-6);
  }
  EXPECT_LT(previous_error, 0.03);  // at delta = 1e-36 m the asymptotic form is within 3 %
}

TEST(PstdLineContact, LargeHalfWidthLimitAndClamp) {
  // delta(a) peaks at a* = 4R'/e with delta_max = 4R' e^-2 and d2(delta)/da2 = -1/R' there, so
  // a* - a ~ sqrt(2 R' (delta_max - delta)) with relative error O(sqrt(eps)).
  const double radius = 1e-7;
  const double a_star = 4.0 * radius / std::numbers::e;
  const double dmax = line_contact_max_interference(radius);
  EXPECT_NEAR(line_contact_interference(a_star, radius) / dmax, 1.0, 1e-15);
  for (double eps : {1e-4, 1e-6, 1e-8}) {
    const double a = line_contact_half_width(dmax * (1.0 - eps), radius);
    const double predicted = std::sqrt(2.0 * radius * dmax * eps);
    EXPECT_NEAR((a_star - a) / predicted, 1.0, 3.0 * std::sqrt(eps)) << eps;
  }
  bool clamped = false;
  EXPECT_DOUBLE_EQ(line_contact_half_width(1.5 * dmax, radius, &clamped), a_star);
  EXPECT_TRUE(clamped);
  EXPECT_EQ(line_contact_half_width(0.0, radius), 0.0);
}

TEST(PstdLineContact, LoadIsTheCylinderHertzLoad) {
  // Johnson (4.45): a^2 = 4 P R / (pi E*) for a cylinder, per unit length.
  const double a = 3e-9, radius = 6e-8, modulus = 85e9;
  EXPECT_NEAR(4.0 * line_contact_load(a, radius, modulus) * radius / (std::numbers::pi * modulus), a * a,
              1e-15 * a * a);
}

TEST(PstdHertz, MatchesTheClassicalSphereRelations) {
  // Worked example: E* = 100 GPa, R = 1 um, delta = 1 nm -> a = 31.6228 nm, P = 4.21637 uN, and the Hertz
  // relations a^3 = 3PR/(4E*), delta = a^2/R, p0 = 3P/(2 pi a^2) = 2 a E*/(pi R).
  const double modulus = 1e11, radius = 1e-6, delta = 1e-9;
  const double a = hertz_half_width(delta, radius);
  const double p = hertz_load(delta, radius, modulus);
  EXPECT_NEAR(a, 31.6227766e-9, 1e-16);
  EXPECT_NEAR(p, 4.21637021e-6, 1e-13);
  EXPECT_NEAR(std::cbrt(3.0 * p * radius / (4.0 * modulus)) / a, 1.0, 1e-14);
  EXPECT_NEAR(3.0 * p / (2.0 * std::numbers::pi * a * a) / (2.0 * a * modulus / (std::numbers::pi * radius)), 1.0,
              1e-14);
  const double h = 1e-6 * delta;
  EXPECT_NEAR((hertz_load(delta + h, radius, modulus) - hertz_load(delta - h, radius, modulus)) / (2 * h) /
                  hertz_stiffness(delta, radius, modulus),
              1.0, 1e-9);
}

TEST(PstdHertz, EffectiveModulusOfSiliconOnSilicon) {
  // E = 161 GPa, nu = 0.23 on both sides: E' = E / (2 (1 - nu^2)) = 84.9963 GPa.
  EXPECT_NEAR(effective_modulus(161e9, 0.23, 161e9, 0.23), 161e9 / (2.0 * (1.0 - 0.23 * 0.23)), 1e-3);
}
