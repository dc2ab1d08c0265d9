// SPDX-License-Identifier: MIT
// Mesh queries, append, validate and scaled_jacobian.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/box.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

// A box named `name` with `intervals` cells, of `size` at `origin` (m).
BoxSpec box(const std::string& name, const std::array<int, 3>& intervals,
            const std::array<double, 3>& origin = {0, 0, 0}, const std::array<double, 3>& size = {1, 1, 1}) {
  BoxSpec s;
  s.name = name;
  s.intervals = intervals;
  s.origin = origin;
  s.size = size;
  return s;
}

Mesh unit_cube() {
  Mesh m;
  m.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  m.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  m.blocks = {{"cube", 0, 1}};
  return m;
}

std::string message_of(const Mesh& m, const std::string& source) {
  try {
    validate(m, source);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshOps, ScaledJacobianOfCubeIsOne) {
  EXPECT_DOUBLE_EQ(scaled_jacobian(unit_cube(), 0), 1.0);
}

TEST(MeshOps, ScaledJacobianOfShearedElementIsCosine) {
  // Shear the top face by s in x: a parallelepiped with edges (1,0,0), (0,1,0), (s,0,1). At every
  // corner det J / (|J1||J2||J3|) = 1 / sqrt(1 + s^2) = cos(shear angle).
  for (double s : {0.3, 1.0, 2.5}) {
    Mesh m = unit_cube();
    for (int n = 4; n < 8; ++n) m.coordinates[3 * n] += s;
    EXPECT_NEAR(scaled_jacobian(m, 0), 1.0 / std::sqrt(1.0 + s * s), 1e-14) << "s = " << s;
    EXPECT_NO_THROW(validate(m, "sheared"));
  }
}

TEST(MeshOps, ScaledJacobianOfDistortedElementIsItsWorstCorner) {
  // Move node 6 from (1,1,1) to (0.75, 0.75, 1). At corner 6 the Jacobian columns are, up to the
  // common factor 1/2, xi: x6 - x7 = (0.75,-0.25,0), eta: x6 - x5 = (-0.25,0.75,0),
  // zeta: x6 - x2 = (-0.25,-0.25,1): det = 0.5, lengths sqrt(0.625), sqrt(0.625), sqrt(1.125).
  // The other corners are milder (corner 5: 0.75/sqrt(0.625) = 0.949; corner 2: 1/sqrt(1.125)).
  Mesh m = unit_cube();
  m.coordinates[18] = 0.75;
  m.coordinates[19] = 0.75;
  const double expected = 0.5 / (0.625 * std::sqrt(1.125));
  EXPECT_NEAR(scaled_jacobian(m, 0), expected, 1e-14);
  EXPECT_NO_THROW(validate(m, "distorted"));
}

TEST(MeshOps, ValidateCatchesInvertedElement) {
  Mesh m = generate_box(box("slab", {3, 2, 2}));
  // Element 7 (0-based 6): swap bottom and top faces -> inside out.
  int* c = &m.connectivity[8 * 6];
  for (int a = 0; a < 4; ++a) std::swap(c[a], c[a + 4]);
  const std::string msg = message_of(m, "generated box slab");
  EXPECT_NE(msg.find("generated box slab: element 7 (block 'slab')"), std::string::npos) << msg;
  EXPECT_NE(msg.find("inverted"), std::string::npos) << msg;
  EXPECT_LT(scaled_jacobian(m, 6), 0.0);
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(MeshOps, ValidateCatchesCornerOnlyInversion) {
  // Push node 6 through the element (past the opposite corner): only some corners invert.
  Mesh m = unit_cube();
  m.coordinates[18] = -0.5;
  m.coordinates[19] = -0.5;
  m.coordinates[20] = -0.5;
  EXPECT_NE(message_of(m, "x").find("element 1"), std::string::npos);
  EXPECT_LE(scaled_jacobian(m, 0), 0.0);
}

TEST(MeshOps, ValidateCatchesBadIndicesBlocksAndSets) {
  Mesh m = unit_cube();
  m.connectivity[3] = 8;
  EXPECT_NE(message_of(m, "f.msh").find("f.msh: element 1 (block 'cube') node 3 refers to node index 8"),
            std::string::npos);
  m = unit_cube();
  m.blocks.clear();
  EXPECT_NE(message_of(m, "f").find("element 1 belongs to no block"), std::string::npos);
  m = unit_cube();
  m.blocks.push_back({"again", 0, 1});
  EXPECT_NE(message_of(m, "f").find("belongs to two blocks"), std::string::npos);
  m = unit_cube();
  m.node_sets["top"] = {4, 9};
  EXPECT_NE(message_of(m, "f").find("node set 'top' refers to node index 9"), std::string::npos);
  m = unit_cube();
  m.side_sets["top"] = {{0, 6}};
  EXPECT_NE(message_of(m, "f").find("side set 'top'"), std::string::npos);
  m = unit_cube();
  m.side_sets["top"] = {{0, 5}};
  m.node_sets["top"] = {4, 5, 6, 7};
  EXPECT_EQ(message_of(m, "f"), "");
}

TEST(MeshOps, SideNodesAndQueries) {
  const Mesh m = unit_cube();
  EXPECT_EQ(m.side_nodes({0, 5}), (std::array<int, 4>{4, 5, 6, 7}));
  EXPECT_EQ(m.side_nodes({0, 3}), (std::array<int, 4>{0, 4, 7, 3}));
  ASSERT_NE(m.find_block("cube"), nullptr);
  EXPECT_EQ(m.find_block("cube")->element_count, 1);
  EXPECT_EQ(m.find_block("nope"), nullptr);
  EXPECT_THROW(m.side_set_nodes("nope"), MeshError);
}

TEST(MeshOps, AppendRenumbers) {
  Mesh m = generate_box(box("sub", {2, 2, 1}));
  const Mesh other = generate_box(box("tip", {1, 1, 3}, {0, 0, 1.5}));
  const int n0 = m.node_count(), e0 = m.element_count();
  append(m, other);
  EXPECT_EQ(m.node_count(), n0 + other.node_count());
  EXPECT_EQ(m.element_count(), e0 + other.element_count());
  ASSERT_NE(m.find_block("tip"), nullptr);
  EXPECT_EQ(m.find_block("tip")->first_element, e0);
  EXPECT_EQ(m.find_block("tip")->element_count, 3);
  for (std::size_t i = 0; i < other.connectivity.size(); ++i)
    EXPECT_EQ(m.connectivity[8 * e0 + i], other.connectivity[i] + n0);
  EXPECT_EQ(m.node_sets.at("tip_zmin").front(), other.node_sets.at("tip_zmin").front() + n0);
  EXPECT_EQ(m.side_sets.at("tip_zmax").front().element, other.side_sets.at("tip_zmax").front().element + e0);
  EXPECT_EQ(m.side_set_nodes("tip_zmax"), m.node_sets.at("tip_zmax"));
  EXPECT_NO_THROW(validate(m, "appended"));
  EXPECT_THROW(append(m, other), MeshError);  // names clash
}

TEST(MeshOps, AddBoxInPlaceEqualsAppend) {
  const BoxSpec a = box("sub", {3, 2, 2});
  BoxSpec b = box("tip", {2, 2, 3}, {0.25, 0.25, 1.0}, {0.5, 0.5, 0.5});
  b.grade_toward = "zmin";
  b.grading_ratio = 1.2;
  Mesh appended = generate_box(a);
  append(appended, generate_box(b));
  Mesh in_place;
  EXPECT_EQ(box_size(a), (std::array<long long, 2>{36, 12}));
  in_place.coordinates.reserve(3 * (box_size(a)[0] + box_size(b)[0]));
  const double* storage = in_place.coordinates.data();
  add_box(in_place, a);
  add_box(in_place, b);
  EXPECT_EQ(in_place.coordinates.data(), storage) << "the reserved room is used, nothing reallocated";
  EXPECT_EQ(in_place.coordinates, appended.coordinates);
  EXPECT_EQ(in_place.connectivity, appended.connectivity);
  EXPECT_EQ(in_place.node_sets, appended.node_sets);
  ASSERT_EQ(in_place.blocks.size(), 2u);
  EXPECT_EQ(in_place.blocks[1].first_element, 12);
  ASSERT_EQ(in_place.side_sets.size(), appended.side_sets.size());
  for (const auto& [name, sides] : appended.side_sets) {
    ASSERT_EQ(in_place.side_sets.at(name).size(), sides.size()) << name;
    for (std::size_t k = 0; k < sides.size(); ++k) {
      EXPECT_EQ(in_place.side_sets.at(name)[k].element, sides[k].element) << name;
      EXPECT_EQ(in_place.side_sets.at(name)[k].face, sides[k].face) << name;
    }
  }
  EXPECT_THROW(add_box(in_place, b), MeshError);  // names clash, as for append
  EXPECT_EQ(in_place.element_count(), 24) << "a clash adds nothing";
}

}  // namespace
}  // namespace tribex::mesh
