// SPDX-License-Identifier: MIT
// Discrete, adhesive and tangential GW models against the continuous Gaussian GW.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/rough/gw_integrals.hpp"
#include "tools/gw/gw_models.hpp"

using namespace tribex::gw;

TEST(DiscreteGw, StratifiedPopulationOf1e5MatchesTheContinuousModelWithin1Percent) {
  const auto pop = stratified_gaussian_population(100000);
  double worst_area = 0.0, worst_load = 0.0;
  for (double t = 0.0; t <= 3.0 + 1e-12; t += 0.25) {
    SCOPED_TRACE(t);
    const auto c = continuous_gw(t), d = discrete_gw(pop, t);
    worst_area = std::max(worst_area, std::fabs(d.area / c.area - 1.0));
    worst_load = std::max(worst_load, std::fabs(d.load / c.load - 1.0));
    EXPECT_NEAR(d.area / c.area, 1.0, 0.01);
    EXPECT_NEAR(d.load / c.load, 1.0, 0.01);
    EXPECT_NEAR(d.count / c.count, 1.0, 0.01);
  }
  std::printf("  stratified 1e5 vs continuous, t in [0, 3]: worst area %.2e, load %.2e (relative)\n", worst_area, worst_load);
}

TEST(DiscreteGw, RandomPopulationOf1e5IsWithinItsSamplingError) {
  // Random draws: the error is statistical. At t = 3 only ~135 of 1e5 asperities touch, so a 1% match
  // is impossible there; we check 4 standard errors, sqrt(Var(f(z))/N) with Var from the continuous model.
  const std::size_t n = 100000;
  const auto pop = gaussian_population(n, 12345);
  for (double t = 0.0; t <= 3.0 + 1e-12; t += 0.5) {
    SCOPED_TRACE(t);
    const auto c = continuous_gw(t), d = discrete_gw(pop, t);
    const double se_area = std::sqrt((gw_integral(2.0, t) - c.area * c.area) / static_cast<double>(n));
    const double se_load = std::sqrt((gw_integral(3.0, t) - c.load * c.load) / static_cast<double>(n));
    EXPECT_NEAR(d.area, c.area, 4 * se_area);
    EXPECT_NEAR(d.load, c.load, 4 * se_load);
    if (t <= 1.5) {  // >= 6700 contacting asperities: within 1% as well
      EXPECT_NEAR(d.area / c.area, 1.0, 0.01 + 4 * se_area / c.area);
    }
  }
}

TEST(DiscreteGw, SingleAsperityIsHertz) {
  const std::vector<double> one{2.0};
  const auto d = discrete_gw(one, 1.0);
  EXPECT_DOUBLE_EQ(d.area, 1.0);
  EXPECT_DOUBLE_EQ(d.load, 1.0);
  EXPECT_DOUBLE_EQ(discrete_gw(one, 1.75).load, std::pow(0.25, 1.5));
}

TEST(DmtGw, AdhesionLowersTheLoadByBetaTimesTheContactFraction) {
  for (double t : {-1.0, 0.0, 1.0, 2.5}) {
    const auto h = continuous_gw(t), a = dmt_gw(t, 0.3);
    EXPECT_DOUBLE_EQ(a.area, h.area);  // Eq. 4.12: DMT leaves the area Hertzian
    EXPECT_NEAR(a.load, h.load - 0.3 * gw_integral(0.0, t), 1e-15);
  }
  // With a finite range z0, the attraction out of contact adds more negative load; compare with a
  // stratified discrete sum (independent of the continuous quadrature).
  const auto pop = stratified_gaussian_population(200000);
  for (double t : {0.0, 1.0, 2.0}) {
    const auto c = dmt_gw(t, 0.3, 0.05), d = dmt_gw_discrete(pop, t, 0.3, 0.05);
    const double tail = c.load - dmt_gw(t, 0.3).load;
    EXPECT_LT(tail, 0.0);
    EXPECT_NEAR(d.load - dmt_gw_discrete(pop, t, 0.3).load, tail, 0.01 * std::fabs(tail));
  }
  // Far from contact (t = 6, z0 = 0.05): almost every asperity sits at gap s >> z0, where the 3-9 law
  // is (4/3) z0^2 / s^2; the load is -beta (4/3) z0^2 E[1/(t - z)^2] to a few percent.
  const double t = 6.0, z0 = 0.05;
  const double expect = -0.3 * (4.0 / 3.0) * z0 * z0 *
                        gauss_legendre([&](double z) { return normal_pdf(z) / ((t - z) * (t - z)); }, -12.0, 4.0, 200);
  EXPECT_NEAR(dmt_gw(t, 0.3, z0).load / expect, 1.0, 0.05);
}

TEST(TangentialGw, LimitsStickSlipAndDiscreteAgreement) {
  const double t = 1.0;
  // Full sliding: tau* times the Hertz area, i.e. F_1(t).
  EXPECT_NEAR(tangential_gw(t, 6.0) / gw_integral(1.0, t), 1.0, 1e-9);
  // Small slip: every contacting asperity still sticks, T = slip F_1/2(t) - O(slip^4).
  EXPECT_NEAR(tangential_gw(t, 1e-2) / (1e-2 * gw_integral(0.5, t)), 1.0, 1e-3);
  EXPECT_DOUBLE_EQ(tangential_gw(t, 0.0), 0.0);
  double prev = -1.0;
  const auto pop = stratified_gaussian_population(100000);
  for (int i = 0; i <= 30; ++i) {
    const double s = 0.1 * i;
    const double c = tangential_gw(t, s);
    EXPECT_GE(c, prev - 1e-14);  // monotone (to round-off on the plateau): asperities only leave the stuck state
    prev = c;
    if (i > 0) {
      EXPECT_NEAR(tangential_gw_discrete(pop, t, s) / c, 1.0, 0.01);
    }
  }
}
