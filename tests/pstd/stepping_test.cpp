// SPDX-License-Identifier: MIT
// The PSTD stepping on a hand-made two-asperity profile whose response follows from Hertz by hand.
//
// Substrate: flat at -20 nm with two parabolic asperities z = -(x - x_k)^2/(2R), R = 100 nm, summits at
// x = 1000 nm (A1) and 2000 nm (A2). Counterface: one flat 1500 nm segment over [300, 1800) nm at travel 0,
// so A1 is under it and A2 lies ahead. 3-D Hertz, constant restoring force R0 = 1.1 C1, where C1 = tau pi R d1
// is the capacity of A1 alone under W (d1 = (3W/(4E'sqrt R))^(2/3)). By hand:
//   travel < ~173 nm: one contact, C1 < R0 -> slides at W without lifting;
//   A2 climbs under the leading edge: two contacts, the area at W grows past R0/tau -> lifts, until A2's summit
//     is inside; then both carry delta* = R0/(2 tau pi R) (capacity = R0) and W* = 2 (4/3) E' sqrt(R) delta*^1.5;
//   A1 leaves over the trailing edge (travel > 700 nm): area at W* shrinks, no lift; alone A2 carries W* with
//     delta = 2^(2/3) delta*, capacity 2^(-1/3) R0 < R0, sliding on.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tools/pstd/model.hpp"
#include "tools/pstd/stepping.hpp"

using namespace tribex::pstd;

namespace {
constexpr double nm = 1e-9;
constexpr double radius = 100 * nm, modulus = 100e9, tau = 100e6, load = 10e-6;

Model two_asperity_model(ContactLaw law) {
  Model m;
  m.dx = nm;
  m.substrate.assign(4000, -20 * nm);
  for (double centre : {1000.0, 2000.0})
    for (int i = 0; i < 4000; ++i) {
      const double x = (i - centre) * nm;
      m.substrate[i] = std::max(m.substrate[i], -x * x / (2 * radius));
    }
  m.segments.push_back(place_in_point_contact(m.substrate, std::vector<double>(1500, 0.0), 300, 0));
  m.curvature_span = 5;
  m.mechanics = Mechanics{law, modulus, 1e-6, tau};
  return m;
}
}  // namespace

TEST(PstdStepping, RestoringPolynomialOfTheReport) {
  const std::vector<double> c{0.5796, 4.3572, 0.1080, 0.0435, -0.0001};
  EXPECT_NEAR(restoring_force(c, 0.0), 0.5796e-6, 1e-18);
  EXPECT_NEAR(restoring_force(c, 1e-6), 5.0882e-6, 1e-17);  // 0.5796 + 4.3572 + 0.1080 + 0.0435 - 0.0001
}

TEST(PstdStepping, PointContactPlacementTouchesAtOnePoint) {
  const Model m = two_asperity_model(ContactLaw::hertz_3d);
  EXPECT_NEAR(m.segments[0].z[700], 0.0, 1e-20);  // the flat counterface rests on A1's summit
  Gap gap(m);
  gap.set_travel(0);
  EXPECT_NEAR(gap.highest(), 0.0, 1e-20);
}

TEST(PstdStepping, LineContactPressInMatchesTheHandSolution) {
  // One contact carries W: per unit depth P = W/D, a = sqrt(4 R P/(pi E')), delta from eq. (2.5), H = -delta.
  const Model m = two_asperity_model(ContactLaw::line_2d);
  Gap gap(m);
  gap.set_travel(0);
  const double h = height_for_force(gap, load, 1e-10);
  const double p = load / m.mechanics.depth;
  const double a = std::sqrt(4 * radius * p / (std::numbers::pi * modulus));
  const double delta = a * a / (4 * radius) * (2 * std::log(4 * radius / a) - 1);
  EXPECT_NEAR(-h / delta, 1.0, 1e-10);
  EXPECT_NEAR(gap.evaluate(h).area / (2 * a * m.mechanics.depth), 1.0, 1e-10);
}

TEST(PstdStepping, TwoAsperityResponseMatchesTheHandSolution) {
  const Model m = two_asperity_model(ContactLaw::hertz_3d);
  const double d1 = std::pow(3 * load / (4 * modulus * std::sqrt(radius)), 2.0 / 3.0);
  const double c1 = tau * std::numbers::pi * radius * d1;
  const double r0 = 1.1 * c1;
  const double d_star = r0 / (2 * tau * std::numbers::pi * radius);
  const double w_star = 2 * 4.0 / 3.0 * modulus * std::sqrt(radius) * std::pow(d_star, 1.5);

  Drive drive;
  drive.normal_force = load;
  drive.restoring_uN_per_um_pow = {r0 * 1e6};
  drive.steps = 900;
  const tribex::pstd::Run run = simulate(m, drive);
  ASSERT_EQ(run.steps.size(), 901u);
  EXPECT_EQ(run.initial_contacts, 1);

  std::size_t lifts = 0;
  for (std::size_t s = 0; s <= 900; ++s) {
    const StepRecord& r = run.steps[s];
    if (r.lifted) {
      ++lifts;
      EXPECT_GE(s, 170u);  // only while A2 climbs under the leading edge
      EXPECT_LE(s, 201u);
    }
    if (s <= 170) {
      EXPECT_EQ(r.contacts, 1) << s;
      EXPECT_NEAR(r.normal_force / load, 1.0, 1e-12) << s;
      EXPECT_NEAR(r.capacity / c1, 1.0, 1e-10) << s;
    } else if (s >= 210 && s <= 690) {
      EXPECT_EQ(r.contacts, 2) << s;
      EXPECT_NEAR(r.normal_force / w_star, 1.0, 1e-9) << s;
      EXPECT_LT(r.capacity, r0) << s;
      EXPECT_NEAR(r.capacity / r0, 1.0, 1e-9) << s;
    } else if (s >= 740) {
      EXPECT_EQ(r.contacts, 1) << s;
      EXPECT_NEAR(r.normal_force / w_star, 1.0, 1e-9) << s;
      EXPECT_NEAR(r.capacity / (std::pow(2.0, -1.0 / 3.0) * r0), 1.0, 1e-9) << s;
    }
  }
  EXPECT_GE(lifts, 5u);
}
