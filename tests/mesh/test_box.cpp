// SPDX-License-Identifier: MIT
// generate_box: counts, coordinates, geometric grading, sets, outward face orientation.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "mesh/box.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 node(const Mesh& m, int n) { return {m.coordinates[3 * n], m.coordinates[3 * n + 1], m.coordinates[3 * n + 2]}; }

Vec3 centroid(const Mesh& m, const int* nodes, int count) {
  Vec3 c{0, 0, 0};
  for (int a = 0; a < count; ++a)
    for (int d = 0; d < 3; ++d) c[d] += node(m, nodes[a])[d] / count;
  return c;
}

/// Area-weighted normal of a quad from its diagonals: n = (x2 - x0) x (x3 - x1) / 2.
Vec3 quad_normal(const Mesh& m, const std::array<int, 4>& q) {
  const Vec3 a = node(m, q[0]), b = node(m, q[1]), c = node(m, q[2]), d = node(m, q[3]);
  const Vec3 d1{c[0] - a[0], c[1] - a[1], c[2] - a[2]}, d2{d[0] - b[0], d[1] - b[1], d[2] - b[2]};
  return {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]), 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
          0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
}

BoxSpec spec(std::array<int, 3> n) {
  BoxSpec s;
  s.name = "sub";
  s.origin = {-1.0, 2.0, 0.5};
  s.size = {2.0, 3.0, 0.25};
  s.intervals = n;
  return s;
}

TEST(Box, CountsAndCoordinates) {
  const Mesh m = generate_box(spec({4, 3, 2}));
  EXPECT_EQ(m.node_count(), 5 * 4 * 3);
  EXPECT_EQ(m.element_count(), 4 * 3 * 2);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "sub");
  EXPECT_EQ(m.blocks[0].element_count, 24);
  // Node (i,j,k) = i + 5(j + 4k) sits at origin + (i dx, j dy, k dz).
  const int n = 3 + 5 * (2 + 4 * 1);
  EXPECT_DOUBLE_EQ(node(m, n)[0], -1.0 + 3 * 0.5);
  EXPECT_DOUBLE_EQ(node(m, n)[1], 2.0 + 2 * 1.0);
  EXPECT_DOUBLE_EQ(node(m, n)[2], 0.5 + 0.125);
  // Element (i,j,k) = i + 4(j + 3k), x fastest: its node 0 is node (i,j,k).
  const int e = 1 + 4 * (2 + 3 * 1);
  EXPECT_EQ(m.connectivity[8 * e], 1 + 5 * (2 + 4 * 1));
  EXPECT_EQ(m.connectivity[8 * e + 6], 2 + 5 * (3 + 4 * 2));
  // Every element is a 0.5 x 1 x 0.125 brick: validate passes, scaled Jacobian is 1.
  EXPECT_NO_THROW(validate(m, "box"));
  for (int el = 0; el < m.element_count(); ++el) EXPECT_NEAR(scaled_jacobian(m, el), 1.0, 1e-14);
}

TEST(Box, SetSizes) {
  const Mesh m = generate_box(spec({4, 3, 2}));
  const std::map<std::string, std::pair<std::size_t, std::size_t>> expected = {
      {"sub_xmin", {3 * 2, 4 * 3}}, {"sub_xmax", {3 * 2, 4 * 3}}, {"sub_ymin", {4 * 2, 5 * 3}},
      {"sub_ymax", {4 * 2, 5 * 3}}, {"sub_zmin", {4 * 3, 5 * 4}}, {"sub_zmax", {4 * 3, 5 * 4}}};
  EXPECT_EQ(m.side_sets.size(), 6u);
  EXPECT_EQ(m.node_sets.size(), 7u);
  for (const auto& [name, sizes] : expected) {
    ASSERT_TRUE(m.side_sets.count(name)) << name;
    EXPECT_EQ(m.side_sets.at(name).size(), sizes.first) << name;
    EXPECT_EQ(m.node_sets.at(name).size(), sizes.second) << name;
    EXPECT_EQ(m.side_set_nodes(name), m.node_sets.at(name)) << name;
  }
  EXPECT_EQ(m.node_sets.at("sub_all").size(), 60u);
  // The xmax nodes all have x = origin + size.
  for (int n : m.node_sets.at("sub_xmax")) EXPECT_DOUBLE_EQ(node(m, n)[0], 1.0);
  for (int n : m.node_sets.at("sub_zmin")) EXPECT_DOUBLE_EQ(node(m, n)[2], 0.5);
}

TEST(Box, SideSetFacesPointOutward) {
  BoxSpec s = spec({3, 2, 4});
  s.grade_toward = "zmax";
  s.grading_ratio = 1.3;
  const Mesh m = generate_box(s);
  const std::map<std::string, Vec3> outward = {{"sub_xmin", {-1, 0, 0}}, {"sub_xmax", {1, 0, 0}},
                                               {"sub_ymin", {0, -1, 0}}, {"sub_ymax", {0, 1, 0}},
                                               {"sub_zmin", {0, 0, -1}}, {"sub_zmax", {0, 0, 1}}};
  for (const auto& [name, dir] : outward)
    for (const Side& side : m.side_sets.at(name)) {
      const auto q = m.side_nodes(side);
      const Vec3 n = quad_normal(m, q);
      const Vec3 fc = centroid(m, q.data(), 4);
      const Vec3 ec = centroid(m, &m.connectivity[8 * side.element], 8);
      const double to_face = (fc[0] - ec[0]) * n[0] + (fc[1] - ec[1]) * n[1] + (fc[2] - ec[2]) * n[2];
      EXPECT_GT(to_face, 0.0) << name << " element " << side.element;  // normal vs element centroid
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      EXPECT_NEAR((n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2]) / len, 1.0, 1e-12) << name;
    }
}

TEST(Box, GeometricGradingTowardZmax) {
  BoxSpec s = spec({1, 1, 6});
  s.grade_toward = "zmax";
  s.grading_ratio = 1.5;
  const Mesh m = generate_box(s);
  // Element heights from the top down: h0, 1.5 h0, ...; h0 = L (r - 1)/(r^n - 1).
  const double L = 0.25, r = 1.5;
  const double h0 = L * (r - 1.0) / (std::pow(r, 6) - 1.0);
  std::vector<double> z;
  for (int k = 0; k <= 6; ++k) z.push_back(node(m, 4 * k)[2]);
  EXPECT_EQ(z.front(), 0.5);
  EXPECT_EQ(z.back(), 0.75);  // total length exact
  EXPECT_NEAR(z[6] - z[5], h0, 1e-15);
  for (int k = 0; k + 1 < 6; ++k) EXPECT_NEAR((z[k + 1] - z[k]) / (z[k + 2] - z[k + 1]), r, 1e-12);
}

TEST(Box, GeometricGradingTowardXmin) {
  BoxSpec s = spec({5, 1, 1});
  s.grade_toward = "xmin";
  s.grading_ratio = 2.0;
  const Mesh m = generate_box(s);
  // h0 (1 + 2 + 4 + 8 + 16) = 2  ->  h0 = 2/31, smallest at x = -1.
  EXPECT_NEAR(node(m, 1)[0] - node(m, 0)[0], 2.0 / 31.0, 1e-15);
  EXPECT_NEAR(node(m, 5)[0] - node(m, 4)[0], 32.0 / 31.0, 1e-14);
  EXPECT_EQ(node(m, 5)[0], 1.0);
}

TEST(Box, BadSpecsAreMeshErrors) {
  BoxSpec s = spec({2, 2, 0});
  EXPECT_THROW(generate_box(s), MeshError);
  s = spec({2, 2, 2});
  s.size[1] = -1.0;
  EXPECT_THROW(generate_box(s), MeshError);
  s = spec({2, 2, 2});
  s.grade_toward = "top";
  s.grading_ratio = 1.2;
  try {
    generate_box(s);
    FAIL() << "expected MeshError";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("xmin, xmax"), std::string::npos) << e.what();
  }
  s.grade_toward = "zmin";
  s.grading_ratio = 0.5;
  EXPECT_THROW(generate_box(s), MeshError);
  s.grade_toward = "";
  s.grading_ratio = 1.2;
  EXPECT_THROW(generate_box(s), MeshError);
}

// Timing is printed, never asserted (house rule: performance figures come from benchmarks).
TEST(Box, PrintsTimingFor100Cubed) {
  BoxSpec s;
  s.intervals = {100, 100, 100};
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh m = generate_box(s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(m.element_count(), 1000000);
  std::printf("[timing] generate_box 100^3 (1e6 hex8, 1030301 nodes): %.3f s\n", seconds);
}

}  // namespace
}  // namespace tribex::mesh
