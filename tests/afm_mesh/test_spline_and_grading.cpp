// SPDX-License-Identifier: MIT
// Cubic splines (natural and not-a-knot ends) and the graded axes of the AFM mesh generator, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "mesh/afm/cubic_spline.hpp"
#include "mesh/afm/graded_axis.hpp"

using namespace tribex::mesh::afm;

TEST(CubicSpline, ReproducesAStraightLineExactlyWithEitherEnds) {
  std::vector<double> y;
  for (int i = 0; i < 9; ++i) y.push_back(2.0 - 0.5 * (0.1 + 0.3 * i));
  for (auto ends : {SplineEnds::natural, SplineEnds::not_a_knot}) {
    const CubicSpline s(0.1, 0.3, y, ends);
    for (double x = 0.1; x <= 2.5; x += 0.037) EXPECT_NEAR(s(x), 2.0 - 0.5 * x, 1e-14);
  }
}

TEST(CubicSpline, NotAKnotReproducesACubicExactly) {
  auto f = [](double x) { return 1.0 - 2.0 * x + 0.7 * x * x - 0.3 * x * x * x; };
  for (int n : {3, 4, 5, 12}) {
    std::vector<double> y;
    for (int i = 0; i < n; ++i) y.push_back(f(-1.0 + 0.25 * i));
    const CubicSpline s(-1.0, 0.25, y, SplineEnds::not_a_knot);
    const double tol = n == 3 ? 1e-2 : 1e-12;  // 3 points: the parabola, not the cubic
    for (double x = -1.0; x <= -1.0 + 0.25 * (n - 1); x += 0.01) EXPECT_NEAR(s(x), f(x), tol) << "n = " << n;
  }
}

// Max error of the spline through sin on [0, 2.5] (f'' != 0 at the right end) with n knots.
double sine_error(int n, SplineEnds ends) {
  const double h = 2.5 / (n - 1);
  std::vector<double> y;
  for (int i = 0; i < n; ++i) y.push_back(std::sin(h * i));
  const CubicSpline s(0.0, h, y, ends);
  double worst = 0.0;
  for (int i = 0; i <= 5000; ++i) worst = std::max(worst, std::abs(s(2.5 * i / 5000.0) - std::sin(2.5 * i / 5000.0)));
  return worst;
}

TEST(CubicSpline, NotAKnotIsFourthOrderUpToTheEndsWhereNaturalIsSecondOrder) {
  const double nak = sine_error(21, SplineEnds::not_a_knot) / sine_error(41, SplineEnds::not_a_knot);
  const double nat = sine_error(21, SplineEnds::natural) / sine_error(41, SplineEnds::natural);
  std::printf("[ spline ] error ratio for h -> h/2: not-a-knot %.2f (16 = 4th order), natural %.2f (4 = 2nd order)\n", nak, nat);
  EXPECT_GT(nak, 12.0);
  EXPECT_LT(nat, 6.0);
  EXPECT_GT(nat, 3.0);
}

TEST(CubicSpline, NaturalInterpolatesASineWithinTheInteriorBound) {
  // sin has f'' = 0 at 0 and pi, so the natural end condition is exact there and the interpolation
  // error is the interior bound (5/384) h^4 max|f''''| (de Boor): 9.6e-6 for h = pi/30.
  const int n = 31;
  const double h = std::numbers::pi / (n - 1);
  std::vector<double> y;
  for (int i = 0; i < n; ++i) y.push_back(std::sin(h * i));
  const CubicSpline s(0.0, h, y, SplineEnds::natural);
  double worst = 0.0;
  for (int i = 0; i <= 3000; ++i) {
    const double x = std::numbers::pi * i / 3000.0;
    worst = std::max(worst, std::abs(s(x) - std::sin(x)));
  }
  EXPECT_LT(worst, 5.0 / 384.0 * std::pow(h, 4));
  EXPECT_GT(worst, 1e-8);  // a cubic does not reproduce a sine: the bound is being exercised
  for (int i = 0; i < n; ++i) EXPECT_NEAR(s(h * i), y[i], 1e-15);
}

TEST(SplineSurface, PassesThroughEveryPixelCentre) {
  HeightMap m;
  m.nx = 7;
  m.ny = 5;
  m.dx = 2e-9;
  m.dy = 3e-9;
  for (std::size_t k = 0; k < m.nx * m.ny; ++k) m.heights.push_back(1e-9 * std::cos(1.7 * static_cast<double>(k)));
  const SplineSurface s(m);
  for (std::size_t iy = 0; iy < m.ny; ++iy)
    for (std::size_t ix = 0; ix < m.nx; ++ix)
      EXPECT_NEAR(s((ix + 0.5) * m.dx, (iy + 0.5) * m.dy), m.at(ix, iy), 1e-22);
}

TEST(GradedAxis, TrackIsUniformAndNeighboursGrowByAtMostTheRatio) {
  const double h = 0.5e-9, r = 1.3;
  const auto x = graded_axis(0.0, 60e-9, 12.5e-9, 47.5e-9, h, r);  // a 35 nm track in a 60 nm window
  ASSERT_GE(x.size(), 72u);
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_EQ(x.back(), 60e-9);
  int in_track = 0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double size = x[i + 1] - x[i];
    EXPECT_GT(size, 0.0);
    const double centre = 0.5 * (x[i] + x[i + 1]);
    if (centre > 12.5e-9 && centre < 47.5e-9) {
      EXPECT_LE(size, h * (1 + 1e-12));
      ++in_track;
    }
    if (i + 2 < x.size()) {
      const double next = x[i + 2] - x[i + 1];
      EXPECT_LE(std::max(size, next) / std::min(size, next), r * (1 + 1e-9)) << "at node " << i;
    }
  }
  EXPECT_EQ(in_track, 70);
  // 12.5 nm margins graded from 0.5 nm: 0.5 (q + ... + q^n) = 12.5 with q <= 1.3 needs n = 8
  // (n = 7 reaches only 11.4 nm).
  EXPECT_EQ(x.size(), 70u + 2 * 8 + 1);
}

TEST(GradedSizes, SumToTheLengthWithTheFewestElements) {
  const auto s = graded_sizes(40e-9, 0.5e-9, 1.3);
  double sum = 0.0;
  for (double v : s) sum += v;
  EXPECT_NEAR(sum, 40e-9, 1e-20);
  // 0.5 (1.3 + ... + 1.3^n) >= 40 first at n = 12 (11 give 36.7 nm).
  EXPECT_EQ(s.size(), 12u);
  EXPECT_LE(s.front(), 0.5e-9 * 1.3 * (1 + 1e-12));
  // Ratio 1: plain uniform elements of at most h.
  const auto u = graded_sizes(2.2e-9, 0.5e-9, 1.0);
  EXPECT_EQ(u.size(), 5u);
  for (double v : u) EXPECT_NEAR(v, 0.44e-9, 1e-22);
  EXPECT_TRUE(graded_sizes(0.0, 0.5e-9, 1.3).empty());
}

TEST(GradedAxis, ASliverMarginIsAbsorbedIntoTheTrack) {
  const auto x = graded_axis(0.0, 10.1e-9, 0.0, 10e-9, 1e-9, 1.3);  // 0.1 nm margin < h/4
  ASSERT_EQ(x.size(), 12u);  // 11 equal elements of 0.918 nm over 10.1 nm
  for (std::size_t i = 0; i + 1 < x.size(); ++i) EXPECT_NEAR(x[i + 1] - x[i], 10.1e-9 / 11, 1e-20);
}
