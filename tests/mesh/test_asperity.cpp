// SPDX-License-Identifier: MIT
// generate_asperity: the quarter model (symmetry = quarter) against the full one, the symmetry
// node sets, the coating block (layers, thickness, bonded to the substrate), and a fine depth
// smaller than the coating (no zero-thickness layer below it); the tip alone placed at an apex position
// (substrate = none, apex position: the tip over an AFM surface); the paraboloid tip profile; every
// violated limit at once with consistent nearest valid values; a fine strip along x longer than the tip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "mesh/asperity.hpp"
#include "mesh/asperity_limits.hpp"
#include "mesh/mesh_error.hpp"
#include "tests/support/asperity_outline.hpp"

namespace tribex::mesh {
namespace {

AsperitySpec coated(bool quarter) {
  AsperitySpec s = test::asperity_outline(27e-9, 14e-9, 6e-9, 30e-9, 15e-9, 0.5e-9);
  s.fine_half_width = 3e-9;
  s.fine_depth = 2.5e-9;
  s.grading_ratio = 1.3;
  s.coating_thickness = 2e-9;
  s.coating_layers = 6;
  s.quarter = quarter;
  return s;
}

// Volume of a hex8 by the 2x2x2 Gauss rule (exact for trilinear maps).
double hex_volume(const Mesh& m, int e) {
  const double g = 1.0 / std::sqrt(3.0);
  const int sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1}, sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  double vol = 0;
  for (int q = 0; q < 8; ++q) {
    const double xi = sx[q] * g, eta = sy[q] * g, zeta = sz[q] * g;
    double J[3][3] = {};
    for (int a = 0; a < 8; ++a) {
      const double d[3] = {0.125 * sx[a] * (1 + sy[a] * eta) * (1 + sz[a] * zeta),
                           0.125 * sy[a] * (1 + sx[a] * xi) * (1 + sz[a] * zeta),
                           0.125 * sz[a] * (1 + sx[a] * xi) * (1 + sy[a] * eta)};
      const double* x = &m.coordinates[3 * m.connectivity[8 * e + a]];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) J[i][j] += d[i] * x[j];
    }
    vol += J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  }
  return vol;
}

double block_volume(const Mesh& m, const std::string& name) {
  const Block* b = m.find_block(name);
  double v = 0;
  for (int e = b->first_element; e < b->first_element + b->element_count; ++e) v += hex_volume(m, e);
  return v;
}

TEST(Asperity, QuarterModelIsAQuarterOfTheFullOne) {
  const Mesh full = generate_asperity(coated(false));
  const Mesh quarter = generate_asperity(coated(true));
  for (const char* b : {"tip", "substrate", "coating"}) {
    ASSERT_NE(quarter.find_block(b), nullptr) << b;
    // Same spacing on x, y >= 0: a quarter of the volume to round-off, and of the elements exactly.
    EXPECT_NEAR(block_volume(quarter, b), 0.25 * block_volume(full, b), 1e-9 * block_volume(full, b)) << b;
    EXPECT_EQ(4 * quarter.find_block(b)->element_count, full.find_block(b)->element_count) << b;
  }
  // Coating: 2 nm thick, 15 x 15 nm in the quarter.
  EXPECT_NEAR(block_volume(quarter, "coating"), 15e-9 * 15e-9 * 2e-9, 1e-12 * 15e-9 * 15e-9 * 2e-9);
  // No coordinate below zero in x or y.
  for (int n = 0; n < quarter.node_count(); ++n) {
    EXPECT_GE(quarter.coordinates[3 * n], 0.0);
    EXPECT_GE(quarter.coordinates[3 * n + 1], 0.0);
  }
}

TEST(Asperity, QuarterSymmetrySetsHoldTheTipAndSubstrateNodesOnThePlanes) {
  const Mesh m = generate_asperity(coated(true));
  for (int axis = 0; axis < 2; ++axis) {
    const auto& set = m.node_sets.at(axis == 0 ? "symmetry_x" : "symmetry_y");
    std::set<int> expected;
    for (int n = 0; n < m.node_count(); ++n)
      if (m.coordinates[3 * n + axis] == 0.0) expected.insert(n);
    EXPECT_EQ(std::set<int>(set.begin(), set.end()), expected) << axis;
    EXPECT_TRUE(std::is_sorted(set.begin(), set.end()));
    // Both bodies contribute: nodes above the substrate top (tip) and below it.
    const bool tip_nodes = std::any_of(set.begin(), set.end(), [&](int n) { return m.coordinates[3 * n + 2] > 1e-10; });
    const bool sub_nodes = std::any_of(set.begin(), set.end(), [&](int n) { return m.coordinates[3 * n + 2] < -1e-10; });
    EXPECT_TRUE(tip_nodes && sub_nodes) << axis;
  }
  // The symmetry planes are not outer sides.
  for (const char* sides : {"substrate_sides", "tip_sides"})
    for (int n : m.node_sets.at(sides)) {
      const double x = m.coordinates[3 * n], y = m.coordinates[3 * n + 1];
      const double half = std::string(sides) == "tip_sides" ? 7e-9 : 15e-9;
      EXPECT_TRUE(std::abs(x - half) < 1e-15 || std::abs(y - half) < 1e-15) << sides << " node " << n;
    }
  EXPECT_EQ(m.node_sets.count("substrate_xmin"), 0u);
  EXPECT_EQ(m.side_sets.count("substrate_xmin"), 0u);
  // The axis node sets sit on the axis.
  for (const char* s : {"tip_axis_top", "tip_apex", "substrate_axis_top", "substrate_axis_bottom"}) {
    const int n = m.node_sets.at(s).at(0);
    EXPECT_EQ(m.coordinates[3 * n], 0.0) << s;
    EXPECT_EQ(m.coordinates[3 * n + 1], 0.0) << s;
  }
}

TEST(Asperity, CoatingLayersAndTheSpacingBelowWhenTheFineDepthIsInsideTheCoating) {
  AsperitySpec s = coated(true);
  s.fine_depth = 1e-9;  // shorter than the 2 nm coating: below it one element of h, then grading
  const Mesh m = generate_asperity(s);
  std::set<double> z;
  for (int n = 0; n < m.node_count(); ++n)
    if (m.coordinates[3 * n + 2] <= 0.0) z.insert(m.coordinates[3 * n + 2]);
  std::vector<double> levels(z.rbegin(), z.rend());  // from the top down
  ASSERT_GE(levels.size(), 9u);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(levels[i] - levels[i + 1], 2e-9 / 6, 1e-18) << i;
  EXPECT_NEAR(levels[6], -2e-9, 1e-18);
  // Below the coating: the first element is h, then growth by the grading ratio.
  EXPECT_NEAR(levels[6] - levels[7], 0.5e-9, 1e-18);
  EXPECT_NEAR((levels[7] - levels[8]) / (levels[6] - levels[7]), 1.3, 1e-9);
  for (std::size_t i = 1; i < levels.size(); ++i) EXPECT_GT(levels[i - 1] - levels[i], 1e-11) << i;
}


TEST(Asperity, TipOnlyPlacedAtTheApexIsTheFullTipTranslated) {
  AsperitySpec full = coated(false);
  full.coating_thickness = 0.0;
  full.gap = 0.3e-9;
  AsperitySpec alone = full;
  alone.tip_only = true;
  alone.place_apex = true;
  alone.apex = {210e-9, 205e-9, 4.5e-9};
  const Mesh a = generate_asperity(full);
  const Mesh b = generate_asperity(alone);
  ASSERT_EQ(b.blocks.size(), 1u);
  EXPECT_EQ(b.blocks[0].name, "tip");
  const Block* tip = a.find_block("tip");
  ASSERT_NE(tip, nullptr);
  EXPECT_EQ(b.element_count(), tip->element_count);
  for (const char* gone : {"substrate_top", "substrate_bottom", "substrate_sides", "substrate_axis_top"}) {
    EXPECT_EQ(b.node_sets.count(gone), 0u) << gone;
    EXPECT_EQ(b.side_sets.count(gone), 0u) << gone;
  }
  for (const char* kept : {"tip_surface", "tip_top", "tip_sides"}) EXPECT_EQ(b.side_sets.count(kept), 1u) << kept;
  // The apex node lands on the requested point; every tip node is the full mesh's tip node moved by
  // (apex x, apex y, apex z - gap), in the same order (the tip's nodes follow the substrate's in a).
  const double* apex = &b.coordinates[3 * b.node_sets.at("tip_apex").at(0)];
  EXPECT_NEAR(apex[0], 210e-9, 1e-18);
  EXPECT_NEAR(apex[1], 205e-9, 1e-18);
  EXPECT_NEAR(apex[2], 4.5e-9, 1e-18);
  const int offset = a.node_count() - b.node_count();
  ASSERT_GT(offset, 0);
  const double shift[3] = {210e-9, 205e-9, 4.5e-9 - 0.3e-9};
  double worst = 0;
  for (int n = 0; n < b.node_count(); ++n)
    for (int i = 0; i < 3; ++i)
      worst = std::max(worst, std::abs(b.coordinates[3 * n + i] - a.coordinates[3 * (n + offset) + i] - shift[i]));
  EXPECT_LT(worst, 1e-18);
  EXPECT_NEAR(block_volume(b, "tip"), block_volume(a, "tip"), 1e-12 * block_volume(a, "tip"));
}

TEST(Asperity, TipProfileIsTheSphereOrHertzsParaboloid) {
  // Every tip_surface node lies on the chosen profile above the apex (gap 0.3 nm): the sphere
  // z = R - sqrt(R^2 - r^2) by default, Hertz's z = r^2/(2R) with `paraboloid`. The two differ by
  // about r^4/(8R^3) (0.057 nm at the column corner here), far above the 1e-18 m tolerance.
  for (const bool paraboloid : {false, true}) {
    AsperitySpec s = coated(false);
    s.gap = 0.3e-9;
    s.paraboloid = paraboloid;
    const Mesh m = generate_asperity(s);
    const auto& surface = m.node_sets.at("tip_surface");
    ASSERT_GT(surface.size(), 100u);
    double worst = 0, largest_r = 0;
    for (const int n : surface) {
      const double* x = &m.coordinates[3 * n];
      const double r2 = x[0] * x[0] + x[1] * x[1], R = s.radius;
      const double z = paraboloid ? r2 / (2 * R) : R - std::sqrt(R * R - r2);
      worst = std::max(worst, std::abs(x[2] - s.gap - z));
      largest_r = std::max(largest_r, std::sqrt(r2));
    }
    EXPECT_LT(worst, 1e-18) << (paraboloid ? "paraboloid" : "sphere");
    EXPECT_NEAR(largest_r, 7e-9 * std::sqrt(2.0), 1e-15);
  }
}

TEST(Asperity, TipOnlyQuarterModelIsRefused) {
  AsperitySpec s = coated(true);
  s.tip_only = true;
  EXPECT_THROW(generate_asperity(s), MeshError);
}

// R = 15 nm with the tip width, tip height and fine half width the user of issue 56 tried in turn.
AsperitySpec three_limits_violated() {
  AsperitySpec s = test::asperity_outline(15e-9, 30e-9, 3e-9, 60e-9, 30e-9, 1e-9);
  s.fine_half_width = 12e-9;
  return s;
}

// The nearest valid value a violation names, m.
double nearest(const AsperityLimitViolation& v) {
  const auto at = v.message.find("nearest valid: ");
  EXPECT_NE(at, std::string::npos) << v.message;
  return std::stod(v.message.substr(at + 15)) * 1e-9;
}

TEST(AsperityLimits, EveryViolatedLimitOnceWithTheNearestValidValue) {
  AsperitySpec s = three_limits_violated();
  const auto v = asperity_limit_violations(s);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].key, "tip width");
  EXPECT_EQ(v[1].key, "tip height");
  EXPECT_EQ(v[2].key, "fine half width");
  // tip width < 0.9 sqrt(2) R = 19.09 nm -> 19 nm; tip height > 2 (R - sqrt(R^2 - w^2/2)) = 16.66 nm for w = 19 nm
  // -> 16.7 nm; fine half width < w/2 = 9.5 nm -> 9.49 nm.
  EXPECT_DOUBLE_EQ(nearest(v[0]), 19e-9);
  EXPECT_NEAR(2 * asperity_corner_sag(s, 19e-9), 2 * (15e-9 - std::sqrt(225e-18 - 0.5 * 361e-18)), 1e-14 * 16.66e-9);
  EXPECT_DOUBLE_EQ(nearest(v[1]), 16.7e-9);
  EXPECT_DOUBLE_EQ(nearest(v[2]), 9.49e-9);
  try {
    generate_asperity(s);
    FAIL() << "meshed";
  } catch (const MeshError& e) {  // one line per violation
    const std::string what = e.what();
    EXPECT_EQ(std::count(what.begin(), what.end(), '\n'), 2) << what;
  }
  // The suggestions taken together mesh.
  s.tip_width = nearest(v[0]);
  s.tip_height = nearest(v[1]);
  s.fine_half_width = nearest(v[2]);
  EXPECT_TRUE(asperity_limit_violations(s).empty());
  EXPECT_NO_THROW(generate_asperity(s));
}

TEST(AsperityLimits, FineXRangeOutsideTheSubstrateAndOnATipOnlyModel) {
  AsperitySpec s = three_limits_violated();
  s.tip_width = 18e-9;
  s.tip_height = 20e-9;
  s.fine_half_width = 4e-9;
  s.fine_x_range = {{2e-9, 31e-9}};  // X0 > 0, X1 beyond substrate width / 2 = 30 nm
  const auto v = asperity_limit_violations(s);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].key, "fine x range");
  EXPECT_NE(v[0].message.find("nearest valid: 0 nm"), std::string::npos) << v[0].message;
  EXPECT_NE(v[1].message.find("nearest valid: 29.9 nm"), std::string::npos) << v[1].message;
  s.fine_x_range = {{-4e-9, 20e-9}};
  s.tip_only = true;
  ASSERT_EQ(asperity_limit_violations(s).size(), 1u);
}

// A slide of 16 nm on R = 15 nm: the substrate's fine strip -4 nm <= x <= 20 nm, far beyond the tip
// column (18 nm wide) that caps the fine half width near 9 nm; every element in it is as asked.
TEST(AsperityLimits, FineXRangeLongerThanTheTipMeshesWithTheAskedElementSize) {
  AsperitySpec s = three_limits_violated();
  s.tip_width = 18e-9;
  s.tip_height = 20e-9;
  s.fine_half_width = 4e-9;
  s.element_size = 0.5e-9;
  s.fine_x_range = {{-4e-9, 20e-9}};
  const Mesh m = generate_asperity(s);
  std::set<double> xs, ys;
  for (int n : m.node_sets.at("substrate_top")) {
    xs.insert(m.coordinates[3 * n]);
    ys.insert(m.coordinates[3 * n + 1]);
  }
  const std::vector<double> x(xs.begin(), xs.end()), y(ys.begin(), ys.end());
  int fine = 0;
  double largest_outside = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double h = x[i] - x[i - 1];
    if (x[i - 1] >= -4e-9 - 1e-15 && x[i] <= 20e-9 + 1e-15) {
      EXPECT_NEAR(h, 0.5e-9, 1e-15) << "between x = " << x[i - 1] << " and " << x[i];
      ++fine;
    } else {
      EXPECT_GT(h, 0.5e-9 * (1 + 1e-9)) << "outside the strip at x = " << x[i];  // graded beyond it
      largest_outside = std::max(largest_outside, h);
    }
  }
  EXPECT_EQ(fine, 48);  // 24 nm / 0.5 nm
  EXPECT_DOUBLE_EQ(x.front(), -30e-9);
  EXPECT_DOUBLE_EQ(x.back(), 30e-9);
  // y keeps the fine half width: fine for |y| <= 4 nm only.
  int fine_y = 0;
  for (std::size_t i = 1; i < y.size(); ++i)
    if (std::fabs(y[i] - y[i - 1] - 0.5e-9) < 1e-15) ++fine_y;
  EXPECT_EQ(fine_y, 16);
  // The tip column keeps its own fine square: |x| <= 4 nm at 0.5 nm.
  std::set<double> tip_x;
  for (int n : m.node_sets.at("tip_top")) tip_x.insert(m.coordinates[3 * n]);
  int tip_fine = 0;
  for (auto it = std::next(tip_x.begin()); it != tip_x.end(); ++it)
    if (std::fabs(*it - *std::prev(it) - 0.5e-9) < 1e-15) ++tip_fine;
  EXPECT_EQ(tip_fine, 16);
  EXPECT_GT(largest_outside, 0.5e-9);
}

}  // namespace
}  // namespace tribex::mesh
