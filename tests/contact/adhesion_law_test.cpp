// SPDX-License-Identifier: MIT
// The Lennard-Jones 3-9 law and the junction shear law against their closed forms (docs/theory.md 6.1,
// 6.3, 7.1).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/models/adhesion_lj.hpp"
#include "contact/models/junction_shear.hpp"

namespace tribex::contact {
namespace {

constexpr double W = 0.05, z0 = 0.2e-9;

TEST(AdhesionLaw, ZeroAtEquilibriumAndPeakAtCubeRootOfThreeSixth) {
  EXPECT_NEAR(lj_traction(z0, W, z0), 0.0, 1e-12 * W / z0);
  // Scan for the peak: sigma_max = 16W/(9 sqrt 3 z0) = 1.0264 W/z0 at h = 3^(1/6) z0 = 1.2009 z0.
  double best = 0.0, h_best = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double h = z0 * (1.0 + 1.0 * i / 200000);
    const double s = lj_traction(h, W, z0);
    if (s > best) best = s, h_best = h;
  }
  EXPECT_NEAR(best / (W / z0), 1.0264, 1e-4);
  EXPECT_NEAR(h_best / z0, 1.2009, 1e-4);
  EXPECT_NEAR(best, 16.0 * W / (9.0 * std::sqrt(3.0) * z0), 1e-9 * best);
  // Attractive beyond z0, repulsive inside.
  EXPECT_GT(lj_traction(1.5 * z0, W, z0), 0.0);
  EXPECT_LT(lj_traction(0.9 * z0, W, z0), 0.0);
  // Stiffness at equilibrium d sigma/dh = 16 W / z0^2.
  const double e = 1e-6 * z0;
  EXPECT_NEAR((lj_traction(z0 + e, W, z0) - lj_traction(z0 - e, W, z0)) / (2 * e), 16 * W / (z0 * z0),
              1e-6 * 16 * W / (z0 * z0));
}

// Composite Simpson on [a, b] with n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

TEST(AdhesionLaw, IntegralIsWorkOfAdhesionMinusTruncatedTail) {
  // Untruncated: int_{z0}^{inf} sigma dh = W (substitute h = z0 / u, integrate u on (0, 1]).
  const double full = simpson([](double u) { return u > 0 ? lj_traction(z0 / u, W, z0) * z0 / (u * u) : 0.0; },
                              0.0, 1.0, 20000);
  EXPECT_NEAR(full / W, 1.0, 1e-6);
  for (double ratio : {3.0, 5.0, 10.0, 20.0}) {
    const AdhesionLaw law{W, z0, ratio * z0};
    // Tail lost by the cut-off: (4/3)(z0/h_c)^2 - (1/3)(z0/h_c)^8 (docs/theory.md 6.3: 14.8 % at 3 z0,
    // 5.3 % at 5 z0, 1.3 % at 10 z0).
    const double tail = 4.0 / 3.0 / (ratio * ratio) - 1.0 / 3.0 / std::pow(ratio, 8);
    const double truncated = simpson([&](double h) { return lj_traction(h, W, z0); }, z0, law.cutoff, 20000);
    EXPECT_NEAR(truncated / W, 1.0 - tail, 1e-7) << ratio;
    // The applied (shifted) law integrates to the captured work, which is that minus the shift.
    const double applied = simpson([&](double g) { return adhesive_traction(g, law); }, 0.0, law.capture_gap(), 20000);
    const double shift = lj_traction(law.cutoff, W, z0) * (law.cutoff - z0);
    EXPECT_NEAR(applied / W, 1.0 - tail - shift / W, 1e-7) << ratio;
    EXPECT_NEAR(captured_work(law), applied, 1e-7 * W) << ratio;
  }
  EXPECT_NEAR(4.0 / 3.0 / 25.0 - 1.0 / 3.0 / std::pow(5.0, 8), 0.0533, 1e-4);
}

TEST(AdhesionLaw, ContinuousAtCutoffAndEnergyIsItsPotential) {
  const AdhesionLaw law{W, z0, 5 * z0};
  const double g_c = law.capture_gap(), e = 1e-9 * z0;
  EXPECT_NEAR(adhesive_traction(g_c - e, law), 0.0, 1e-6 * W / z0);
  EXPECT_EQ(adhesive_traction(g_c + e, law), 0.0);
  EXPECT_EQ(adhesive_energy(g_c + e, law), 0.0);
  EXPECT_NEAR(adhesive_energy(g_c - e, law), 0.0, 1e-9 * W);
  EXPECT_EQ(adhesive_traction(-0.1 * z0, law), 0.0);  // penalty contact: no adhesion
  EXPECT_EQ(adhesive_energy(-0.1 * z0, law), adhesive_energy(0.0, law));
  // dU/dg = sigma_s (U is the potential whose force the manager applies).
  for (double g : {0.05 * z0, 0.2 * z0, 0.7 * z0, 2.0 * z0, 3.5 * z0}) {
    const double d = 1e-5 * z0;
    const double dU = (adhesive_energy(g + d, law) - adhesive_energy(g - d, law)) / (2 * d);
    EXPECT_NEAR(dU, adhesive_traction(g, law), 1e-6 * W / z0) << g / z0;
  }
  // Peak of the applied law sits at g = 0.2009 z0.
  EXPECT_NEAR(adhesive_traction(0.2009 * z0, law) + lj_traction(law.cutoff, W, z0), 1.0264 * W / z0,
              1e-4 * W / z0);
}

TEST(JunctionLaw, TanhOpposesSlipAndIsSmoothAtZero) {
  const JunctionLaw law{100e6, 0.5, 0.0};
  double tau[3];
  const double v1[3] = {10.0, 0.0, 0.0};  // 20 v_ref
  junction_traction(v1, law, tau);
  EXPECT_NEAR(tau[0], -100e6 * std::tanh(20.0), 1e-6);
  EXPECT_EQ(tau[1], 0.0);
  const double v2[3] = {0.0, -0.5, 0.0};  // v_ref: 0.7616 tau*
  junction_traction(v2, law, tau);
  EXPECT_NEAR(tau[1], 0.76159416 * 100e6, 1.0);
  EXPECT_EQ(tau[0], 0.0);
  // Oblique: magnitude tau* tanh(|v|/v_ref), direction -v/|v|.
  const double v3[3] = {0.3, 0.4, 0.0};
  junction_traction(v3, law, tau);
  EXPECT_NEAR(std::hypot(tau[0], tau[1]), 100e6 * std::tanh(1.0), 1.0);
  EXPECT_NEAR(tau[0] / tau[1], 0.75, 1e-12);
  // Near zero slip: the damper -(tau*/v_ref) v_t, continuous across the series switch-over.
  const double v4[3] = {1e-9, 0.0, 0.0}, v5[3] = {0.0, 0.0, 0.0};
  junction_traction(v4, law, tau);
  EXPECT_NEAR(tau[0], -100e6 / 0.5 * 1e-9, 1e-9);
  junction_traction(v5, law, tau);
  EXPECT_EQ(tau[0], 0.0);
}

}  // namespace
}  // namespace tribex::contact
