// SPDX-License-Identifier: MIT
// The rough-surface (GW) interaction law (contact/models/rough_surface): the start-up table against
// the GW integrals evaluated directly, the docs/theory.md 10.4 handle, and the discrete law against an
// independent direct sum over a map's summits (tools/surface/summit_contact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "contact/models/rough_surface.hpp"
#include "contact/rough/gw_integrals.hpp"
#include "mesh/afm/height_map.hpp"
#include "tools/surface/spectral_moments.hpp"
#include "tools/surface/summit_contact.hpp"

namespace tribex::contact {
namespace {

// docs/theory.md 10.4 verification handle (alpha = 10): eta = 3.0629e-3 nm^-2, R_s = 21.019 nm,
// sigma_s = 0.95411 nm, E* = 84.1 GPa.
RoughSurfaceParameters handle(double work = 0.0) {
  RoughSurfaceParameters q;
  q.summit_density = 3.0629e-3 * 1e18;
  q.summit_radius = 21.019e-9;
  q.sigma_s = 0.95411e-9;
  q.composite_modulus = 84.1e9;
  q.work_of_adhesion = work;
  return q;
}

TEST(RoughSurfaceLaw, ContinuousMatchesPhysicsHandleAtUnitSeparation) {
  const RoughSurfaceLaw law(handle());
  const auto s = law.evaluate(1.0 * handle().sigma_s);
  // A_c/A0 = 0.016077, P/A0 = 0.11104 GPa (5 digits quoted: 5e-5 relative).
  EXPECT_NEAR(s.area_fraction, 0.016077, 5e-5 * 0.016077);
  EXPECT_NEAR(s.pressure, 0.11104e9, 5e-5 * 0.11104e9);
  EXPECT_NEAR(s.contact_density, handle().summit_density * 0.5 * std::erfc(1.0 / std::sqrt(2.0)), 1e-9 * s.contact_density);
}

// The table must reproduce the direct integrals well inside the 0.5 % acceptance of the FE check:
// Hermite cubics with exact slopes at spacing 0.02 sigma_s give about h^4 t^4 / 384 relative.
TEST(RoughSurfaceLaw, TableMatchesDirectIntegralsOffTheGrid) {
  for (double work : {0.0, 0.5}) {
    const RoughSurfaceLaw law(handle(work));
    const double sigma = handle().sigma_s;
    const double hertz_scale = handle().summit_density * (4.0 / 3.0) * handle().composite_modulus *
                               std::sqrt(handle().summit_radius) * std::pow(sigma, 1.5);
    double worst_p = 0.0, worst_a = 0.0, worst_n = 0.0, worst_k = 0.0;
    for (int i = 0; i <= 997; ++i) {
      const double t = -4.0 + 9.5 * i / 997.0 + 0.0037;  // [-4, 5.5], off the table nodes
      const auto a = law.evaluate(t * sigma), b = law.evaluate_direct(t * sigma);
      // Pressure with adhesion crosses zero: relative to the Hertz part there.
      const double p_ref = std::max(std::abs(b.pressure), 1e-300);
      const double hertz = hertz_scale * gw::gw_integral(1.5, t);
      worst_p = std::max(worst_p, std::abs(a.pressure - b.pressure) / (work > 0 ? hertz : p_ref));
      worst_a = std::max(worst_a, std::abs(a.area_fraction / b.area_fraction - 1));
      worst_n = std::max(worst_n, std::abs(a.contact_density / b.contact_density - 1));
      worst_k = std::max(worst_k, std::abs(a.stiffness / b.stiffness - 1));
    }
    std::printf("W = %g J/m^2: worst table error on t in [-4, 5.5]: pressure %.2e, area %.2e, count %.2e, stiffness %.2e\n",
                work, worst_p, worst_a, worst_n, worst_k);
    EXPECT_LT(worst_p, 1e-6) << "W = " << work;
    EXPECT_LT(worst_a, 1e-6);
    EXPECT_LT(worst_n, 1e-6);
    EXPECT_LT(worst_k, 1e-4);  // the stiffness is the interpolant's slope: one order lower
  }
}

TEST(RoughSurfaceLaw, StiffnessIsMinusThePressureSlope) {
  const RoughSurfaceLaw law(handle());
  const double sigma = handle().sigma_s, e = 1e-4 * sigma;
  for (double t : {-2.0, 0.0, 1.3, 3.0}) {
    const double slope = -(law.evaluate_direct(t * sigma + e).pressure - law.evaluate_direct(t * sigma - e).pressure) / (2 * e);
    EXPECT_NEAR(law.evaluate(t * sigma).stiffness, slope, 1e-6 * slope) << "t = " << t;
  }
  EXPECT_EQ(law.evaluate(6.01 * sigma).pressure, 0.0);
  EXPECT_GT(law.evaluate(-9.0 * sigma).pressure, law.evaluate(-8.0 * sigma).pressure);  // stays repulsive below the table
}

TEST(RoughSurfaceLaw, DiscreteFiveSummitsByHand) {
  RoughSurfaceParameters q;
  q.composite_modulus = 100e9;
  q.work_of_adhesion = 0.1;
  q.summit_heights = {1e-9, -1e-9, 2e-9, 0.0, -2e-9};  // mean 0
  q.summit_radii = {10e-9, 20e-9, 30e-9, 40e-9, 50e-9};
  q.map_area = 1e-14;
  const RoughSurfaceLaw law(q);
  EXPECT_NEAR(law.contact_separation(), 2e-9, 1e-20);
  const double d = 0.5e-9;  // touches the summits at 1 nm (w = 0.5 nm) and 2 nm (w = 1.5 nm)
  const double p = (4.0 / 3.0) * 100e9 * (std::sqrt(10e-9) * std::pow(0.5e-9, 1.5) + std::sqrt(30e-9) * std::pow(1.5e-9, 1.5)) -
                   2 * M_PI * 0.1 * (10e-9 + 30e-9);
  const auto s = law.evaluate(d);
  EXPECT_NEAR(s.pressure, p / 1e-14, 1e-12 * std::abs(p / 1e-14));
  EXPECT_NEAR(s.area_fraction, M_PI * (10e-9 * 0.5e-9 + 30e-9 * 1.5e-9) / 1e-14, 1e-15);
  EXPECT_NEAR(s.contact_density, 2 / 1e-14, 1e-3);
}

// A few-asperity surface (a synthetic map with a handful of bumps), the discrete law against
// the map route's own direct sum (summit_contact: flat at height h above the map mean).
TEST(RoughSurfaceLaw, DiscreteLoadAreaCurveMatchesDirectSummitSum) {
  // A synthetic height map with a handful of bumps (cosines) on a 64 x 64 grid of 2 nm spacing.
  mesh::afm::HeightMap map;
  map.nx = map.ny = 64;
  map.dx = map.dy = 2e-9;
  map.heights.resize(64 * 64);
  for (std::size_t j = 0; j < 64; ++j)
    for (std::size_t i = 0; i < 64; ++i) {
      const double x = i * 2e-9, y = j * 2e-9;
      map.heights[j * 64 + i] = 1e-9 * std::cos(2 * M_PI * x / 40e-9) * std::cos(2 * M_PI * y / 52e-9) +
                          0.3e-9 * std::sin(2 * M_PI * x / 23e-9 + 0.4) * std::cos(2 * M_PI * y / 17e-9);
    }
  const double mean = std::accumulate(map.heights.begin(), map.heights.end(), 0.0) / static_cast<double>(map.heights.size());
  for (double& z : map.heights) z -= mean;
  std::vector<surface::Summit> summits = surface::find_summits(map);
  std::erase_if(summits, [](const surface::Summit& s) { return !(s.curvature > 0.0); });
  ASSERT_GE(summits.size(), 3u);
  ASSERT_LE(summits.size(), 60u);  // "few asperities"
  RoughSurfaceParameters q;
  q.composite_modulus = 90e9;
  q.work_of_adhesion = 0.05;
  q.map_area = 64 * 2e-9 * 64 * 2e-9;
  double zbar = 0.0;
  for (const auto& s : summits) {
    q.summit_heights.push_back(s.height);
    q.summit_radii.push_back(1.0 / s.curvature);
    zbar += s.height / static_cast<double>(summits.size());
  }
  const RoughSurfaceLaw law(q);
  double top = -1e300;
  for (const auto& s : summits) top = std::max(top, s.height);
  int points = 0;
  double worst = 0.0;
  for (int k = 1; k <= 40; ++k) {
    const double h = top - (top - zbar + 0.5e-9) * k / 40.0;  // flat height above the map mean
    const auto direct = surface::summit_contact(summits, q.composite_modulus, q.work_of_adhesion, h);
    const auto s = law.evaluate(h - zbar);  // the law measures d from the mean summit height
    EXPECT_NEAR(s.area_fraction * q.map_area, direct.area, 0.01 * direct.area) << "h = " << h;
    EXPECT_NEAR(s.pressure * q.map_area, direct.load_dmt, 0.01 * std::abs(direct.load_dmt)) << "h = " << h;
    EXPECT_NEAR(s.contact_density * q.map_area, static_cast<double>(direct.contacts), 1e-9);
    worst = std::max({worst, std::abs(s.area_fraction * q.map_area / direct.area - 1),
                      std::abs(s.pressure * q.map_area / direct.load_dmt - 1)});
    ++points;
  }
  std::printf("%zu summits: worst relative difference of load and area from the direct sum %.2e\n", summits.size(), worst);
  EXPECT_EQ(points, 40);
}

TEST(RoughSurfaceLaw, RejectsBadParameters) {
  RoughSurfaceParameters q = handle();
  q.sigma_s = 0.0;
  EXPECT_THROW(RoughSurfaceLaw{q}, std::invalid_argument);
  q = handle();
  q.summit_heights = {1e-9};
  q.summit_radii = {};
  q.map_area = 1e-12;
  EXPECT_THROW(RoughSurfaceLaw{q}, std::invalid_argument);
}

}  // namespace
}  // namespace tribex::contact
