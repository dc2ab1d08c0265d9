// SPDX-License-Identifier: MIT
// The Lennard-Jones sphere-flat reference (tools/adhesion, docs/theory.md 6.7) against its limits:
// the ring kernel against closed forms, Hertz at W = 0, DMT at mu_T = 0.01, JKR at mu_T = 10
// (load- and displacement-controlled pull-off), Maugis-Dugdale in between, grid convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tools/adhesion/curve.hpp"
#include "tools/adhesion/kernel.hpp"
#include "tools/adhesion/report.hpp"
#include "tools/fit/maugis_dugdale.hpp"

namespace {

using namespace tribex::adhesion;

const double e_star = 85e9, z0 = 0.3e-9, work = 0.05;

// A problem at Tabor parameter mu (tools/adhesion/solver.hpp problem_at_tabor).
Problem at_tabor(double mu) { return problem_at_tabor(mu, e_star, work, z0); }

Curve traced(const Problem& pb, double max_load_bar = 3, double resolution = 8) {
  CurveSettings set;
  set.points_per_length = resolution;
  set.max_load = max_load_bar * M_PI * pb.law.captured_work() * pb.radius;
  return trace_curve(pb, set);
}

TEST(AdhesionKernel, RingsAddUpToTheDiskAndTheHertzDisplacement) {
  // A uniform pressure on a disk of radius b: centre 2 b/E*, edge 4 b/(pi E*) (Johnson 3.39).
  const double b = 2e-9;
  std::vector<double> edges;
  for (int i = 0; i <= 40; ++i) edges.push_back(b * i / 40.0);
  const auto c = ring_influence({0.0, b, 3 * b}, edges, e_star);
  double centre = 0, edge = 0, far = 0;
  for (int j = 0; j < 40; ++j) centre += c[j], edge += c[40 + j], far += c[80 + j];
  EXPECT_NEAR(centre * e_star / b, 2.0, 1e-12);
  EXPECT_NEAR(edge * e_star / b, 4 / M_PI, 1e-12);
  EXPECT_NEAR(far, 4 / (M_PI * e_star) * disk_displacement_scaled(3 * b, b), 1e-12 * far);
  // Hertz pressure p0 sqrt(1 - r^2/a^2): u = pi p0 (2a^2 - r^2)/(4 a E*) inside (Johnson 4.23, composite).
  const double a = 1e-9, p0 = 1e9;
  const int n = 2000;
  std::vector<double> e2, mid;
  for (int i = 0; i <= n; ++i) e2.push_back(a * (1 - std::pow(1.0 - static_cast<double>(i) / n, 2)));
  for (int i = 0; i < n; ++i) mid.push_back(0.5 * (e2[i] + e2[i + 1]));
  const std::vector<double> at = {0.0, 0.5 * a, 0.9 * a};
  const auto h = ring_influence(at, e2, e_star);
  for (std::size_t i = 0; i < at.size(); ++i) {
    double u = 0;
    for (int j = 0; j < n; ++j) u += h[i * n + j] * p0 * std::sqrt(1 - mid[j] * mid[j] / (a * a));
    EXPECT_NEAR(u / (M_PI * p0 * (2 * a * a - at[i] * at[i]) / (4 * a * e_star)), 1.0, 2e-4) << at[i];
  }
}

TEST(AdhesionReference, WithoutAdhesionItIsHertz) {
  Problem pb = at_tabor(1);
  pb.radius = 27e-9;
  pb.law.law.work = 0;
  pb.contact_gap = 0;
  CurveSettings set;
  set.max_load = 50e-9;
  const Curve c = trace_curve(pb, set);
  int checked = 0;
  for (const auto& p : c.points) {
    if (p.contact_radius < 0.5e-9) continue;  // a above a few rings' width of the 0.3 nm z0 scale
    const double hertz_load = 4.0 / 3 * e_star * std::sqrt(pb.radius) * std::pow(p.approach, 1.5);
    EXPECT_NEAR(p.load / hertz_load, 1.0, 0.01) << p.contact_radius;
    EXPECT_NEAR(p.contact_radius / std::sqrt(pb.radius * p.approach), 1.0, 0.01) << p.contact_radius;
    ++checked;
  }
  EXPECT_GT(checked, 20);
  EXPECT_GT(c.points.back().load, 50e-9);
}

TEST(AdhesionReference, SmallTaborParameterIsDmt) {
  const Problem pb = at_tabor(0.01);
  const Curve c = traced(pb);
  const double bar = c.pull_off.load / (M_PI * pb.law.captured_work() * pb.radius);
  EXPECT_NEAR(bar, -2.0, 0.02);  // measured -1.9976
  EXPECT_FALSE(c.jump_in.found);
  EXPECT_FALSE(c.jump_out.found);
}

TEST(AdhesionReference, LargeTaborParameterIsJkr) {
  const Problem pb = at_tabor(10);
  const Curve c = traced(pb, 1.0);
  const double scale = M_PI * pb.law.captured_work() * pb.radius;
  EXPECT_NEAR(c.pull_off.load / scale, -1.5, 0.015);           // load control; measured -1.50376 (+0.25 %)
  ASSERT_TRUE(c.jump_out.found);
  EXPECT_NEAR(c.jump_out.load / scale, -5.0 / 6.0, 5.0 / 600);  // displacement control; measured -0.83342 (+0.01 %)
  ASSERT_TRUE(c.jump_in.found);
  // JKR (8.3): the fixed-grip instability at a_bar^3 = 1/6, delta_bar = a^2 - (2/3) sqrt(6 a).
  const Scales s = scales_of(pb);
  const double a3 = std::cbrt(1.0 / 6), jkr_delta = a3 * a3 - 2.0 / 3 * std::sqrt(6 * a3);
  EXPECT_NEAR(c.jump_out.approach / s.approach, jkr_delta, 0.03 * std::abs(jkr_delta));
  EXPECT_NEAR(c.jump_out.bonded_radius / s.radius, a3, 0.05 * a3);
}

// The LJ pull-off against the Dugdale neighbour at lambda = 1.157 mu_T (docs/theory.md 6.7.8 table).
TEST(AdhesionReference, MaugisDugdaleWithinAFewPerCent) {
  for (double lambda : {0.1, 0.5, 1.0, 2.0, 5.0}) {
    const Problem pb = at_tabor(lambda / 1.157);
    const Curve c = traced(pb, 1.0);
    const Scales s = scales_of(pb);
    const double lj = c.pull_off.load / s.load;
    const double md = tribex::fit::MaugisDugdale(s.lambda).pull_off().p_bar;
    EXPECT_NEAR(lj / md - 1, 0.0, 0.06) << "lambda " << lambda << ": LJ " << lj << ", MD " << md;
  }
}

TEST(AdhesionReference, ConvergedInTheRingSpacing) {
  const Problem pb = at_tabor(1);
  const Curve c8 = traced(pb, 1.0, 8), c24 = traced(pb, 1.0, 24);
  EXPECT_NEAR(c8.pull_off.load / c24.pull_off.load, 1.0, 1e-3);
  ASSERT_TRUE(c8.jump_out.found && c24.jump_out.found);
  EXPECT_NEAR(c8.jump_out.load / c24.jump_out.load, 1.0, 2e-3);
  EXPECT_NEAR((c8.jump_out.approach - c24.jump_out.approach) / z0, 0.0, 0.01);
  EXPECT_NEAR((c8.jump_in.approach - c24.jump_in.approach) / z0, 0.0, 0.01);
}

TEST(AdhesionReference, MarkersOfASyntheticPath) {
  Curve c;
  // delta rises to 1 (jump-in), falls to -1, rises again; load minimum at index 4.
  const std::vector<double> d = {-3, -1, 1, 0, -1, 0, 2}, p = {0, -1, -2, -3, -4, -2, 5};
  for (std::size_t i = 0; i < d.size(); ++i) {
    CurvePoint q;
    q.parameter = static_cast<double>(i);
    q.approach = d[i];
    q.load = p[i];
    c.points.push_back(q);
  }
  const auto m = find_markers(c);
  EXPECT_EQ(m.pull_off, 4u);
  ASSERT_TRUE(m.jump_in && m.jump_out);
  EXPECT_EQ(*m.jump_in, 2u);
  EXPECT_EQ(*m.jump_out, 4u);
}

}  // namespace
