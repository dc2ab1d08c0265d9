// SPDX-License-Identifier: MIT
// The attraction of the non-contacting area of a rough surface (contact/rough/noncontact_attraction,
// docs/theory.md 10.8): the start-up table against the quadrature, the flat-flat limit (sigma -> 0) and
// the Hamaker far field of a Gaussian surface, and the rough-surface law with the term switched on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/models/rough_surface.hpp"
#include "contact/rough/noncontact_attraction.hpp"

namespace tribex::contact {
namespace {

constexpr double nm = 1e-9, W = 0.1, z0 = 0.2 * nm;

TEST(NoncontactAttraction, TableMatchesTheQuadrature) {
  const NoncontactAttraction a({W, z0, 200 * z0}, 1.536 * nm);
  double p_max = 0.0, slope_max = 0.0, p_err = 0.0, slope_err = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double d = -4 * nm + i * (a.reach() + 4 * nm) / 400;
    const auto table = a.evaluate(d), direct = a.evaluate_direct(d);
    p_max = std::max(p_max, std::abs(direct.pressure));
    slope_max = std::max(slope_max, std::abs(direct.slope));
    p_err = std::max(p_err, std::abs(table.pressure - direct.pressure));
    slope_err = std::max(slope_err, std::abs(table.slope - direct.slope));
  }
  EXPECT_GT(p_max, 0.0);
  EXPECT_LT(p_err, 1e-6 * p_max);
  EXPECT_LT(slope_err, 1e-4 * slope_max);
  EXPECT_EQ(a.evaluate(a.reach() + nm).pressure, 0.0);
}

TEST(NoncontactAttraction, SmoothSurfacesGiveTheFlatFlatLaw) {
  // sigma << the gap: the Gaussian average of the law is the law at the mean gap (error ~ sigma^2 p''/2).
  const AdhesionLaw law{W, z0, 20 * z0};
  const NoncontactAttraction a(law, 0.005 * nm);
  for (double d : {0.1 * nm, 0.5 * nm, 2.0 * nm}) {
    const double flat = adhesive_traction(d, law);
    EXPECT_NEAR(a.evaluate_direct(d).pressure, flat, 1e-3 * flat) << d;
  }
}

TEST(NoncontactAttraction, FarFieldIsTheHamakerLawAveragedOverTheHeights) {
  // d + z0 = D >> z0: sigma_s -> (8 W z0^2 / 3) (D - z)^-3 - sigma_a(h_c), and the Gaussian mean of
  // (D - z)^-3 is D^-3 (1 + 6 s^2 + 45 s^4 + 420 s^6 + ...), s = sigma / D (0.5 % left at s = 0.15).
  const double sigma = 1.5 * nm, d = 10 * nm, D = d + z0;
  const AdhesionLaw law{W, z0, 500 * z0};
  const NoncontactAttraction a(law, sigma);
  const double s2 = sigma * sigma / (D * D);
  const double mean_inverse_cube = (1 + 6 * s2 + 45 * s2 * s2 + 420 * s2 * s2 * s2) / (D * D * D);
  const double expected = 8 * W * z0 * z0 / 3 * mean_inverse_cube - lj_traction(law.cutoff, W, z0);
  EXPECT_NEAR(a.evaluate_direct(d).pressure, expected, 0.01 * expected);
}

TEST(NoncontactAttraction, RoughSurfaceLawAddsItAsAPullEverywhereItReaches) {
  RoughSurfaceParameters q;
  q.summit_density = 3.796e16;  // di-5 (inputs/examples/clamp_friction)
  q.summit_radius = 14.71 * nm;
  q.sigma_s = 1.536 * nm;
  q.composite_modulus = 84.1e9;
  q.work_of_adhesion = W;
  const RoughSurfaceLaw gw(q);
  q.noncontact_z0 = z0;
  q.noncontact_cutoff = 200 * z0;
  const RoughSurfaceLaw with(q);
  const NoncontactAttraction alone({W, z0, 200 * z0}, q.sigma_s);
  EXPECT_NEAR(with.reach(), alone.reach(), 1e-15);
  EXPECT_GT(with.reach(), gw.contact_separation());
  for (double t : {3.7, 4.9, 7.0}) {
    const double d = t * q.sigma_s;
    const auto a = gw.evaluate(d), b = with.evaluate(d);
    const double pull = alone.evaluate(d).pressure;
    EXPECT_GT(pull, 0.0);
    EXPECT_DOUBLE_EQ(b.noncontact, pull);
    EXPECT_NEAR(b.pressure, a.pressure - pull, 1e-12 * std::abs(a.pressure) + 1e-9);
    EXPECT_NEAR(b.adhesion, a.adhesion + pull, 1e-12 * (a.adhesion + pull));
    EXPECT_DOUBLE_EQ(b.area_fraction, a.area_fraction);
    // The stable step sees the attraction's slope in magnitude on top of the Hertz stiffness.
    EXPECT_NEAR(b.stiffness, a.stiffness + std::abs(alone.evaluate(d).slope), 1e-12 * b.stiffness);
    const auto direct = with.evaluate_direct(d);
    EXPECT_NEAR(direct.pressure, b.pressure, 1e-6 * std::abs(b.pressure) + 1e-6 * pull);
  }
}

}  // namespace
}  // namespace tribex::contact
