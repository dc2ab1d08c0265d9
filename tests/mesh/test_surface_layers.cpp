// SPDX-License-Identifier: MIT
// Surface layer blocks (mesh/surface_layers.hpp): layer counts, contiguity, side sets carried
// through the renumbering, a split that takes the whole block, and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "mesh/box.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/surface_layers.hpp"

namespace tribex::mesh {
namespace {

// 4x4x4 unit box "cube": elements i + 4 (j + 4 k), k = 3 the top layer (side set cube_zmax).
Mesh box4() {
  BoxSpec s;
  s.name = "cube";
  s.intervals = {4, 4, 4};
  return generate_box(s);
}

// Centroid z of element e, to tell the layers apart after the renumbering.
double centre_z(const Mesh& m, int e) {
  double z = 0.0;
  for (int a = 0; a < 8; ++a) z += m.coordinates[3 * m.connectivity[8 * e + a] + 2];
  return z / 8.0;
}

TEST(SurfaceLayers, LayerCountsOnABox) {
  for (int layers : {1, 2, 3}) {
    Mesh m = box4();
    const auto counts = split_surface_layers(m, {"cube", "cube_zmax", layers, "skin"});
    EXPECT_EQ(counts.skin, 16 * layers) << layers;
    EXPECT_EQ(counts.rest, 64 - 16 * layers) << layers;
    ASSERT_EQ(m.blocks.size(), 2u);
    EXPECT_EQ(m.blocks[0].name, "cube");
    EXPECT_EQ(m.blocks[0].first_element, 0);
    EXPECT_EQ(m.blocks[0].element_count, 64 - 16 * layers);
    EXPECT_EQ(m.blocks[1].name, "skin");
    EXPECT_EQ(m.blocks[1].first_element, 64 - 16 * layers);  // contiguous, right after its parent
    EXPECT_EQ(m.blocks[1].element_count, 16 * layers);
    // The skin is the top `layers` layers: centroids above 1 - layers/4, the rest below.
    const double cut = 1.0 - 0.25 * layers;
    for (int e = 0; e < 64; ++e) EXPECT_EQ(centre_z(m, e) > cut, e >= 64 - 16 * layers) << "element " << e;
    validate(m, "split box");
  }
}

TEST(SurfaceLayers, NodeSetSurfaceGivesTheSameLayers) {
  Mesh a = box4(), b = box4();
  split_surface_layers(a, {"cube", "cube_zmax", 2, "skin"});
  b.side_sets.erase("cube_zmax");  // the node set of the same name is used
  split_surface_layers(b, {"cube", "cube_zmax", 2, "skin"});
  EXPECT_EQ(a.connectivity, b.connectivity);
}

TEST(SurfaceLayers, SideSetsFollowTheirElements) {
  const Mesh before = box4();
  Mesh m = before;
  split_surface_layers(m, {"cube", "cube_zmax", 1, "skin"});
  ASSERT_EQ(m.side_sets.size(), before.side_sets.size());
  for (const auto& [name, sides] : before.side_sets) {
    const auto& after = m.side_sets.at(name);
    ASSERT_EQ(after.size(), sides.size()) << name;
    EXPECT_TRUE(std::is_sorted(after.begin(), after.end())) << name;
    // Same faces (as node quadruples) before and after.
    std::multiset<std::array<int, 4>> q0, q1;
    for (const auto& s : sides) q0.insert(before.side_nodes(s));
    for (const auto& s : after) q1.insert(m.side_nodes(s));
    EXPECT_EQ(q0, q1) << name;
  }
  // The top faces now all belong to the skin block (elements 48..63).
  for (const auto& s : m.side_sets.at("cube_zmax")) EXPECT_GE(s.element, 48);
  for (const auto& s : m.side_sets.at("cube_zmin")) EXPECT_LT(s.element, 48);
  EXPECT_EQ(m.node_sets, before.node_sets);
  EXPECT_EQ(m.coordinates, before.coordinates);
}

TEST(SurfaceLayers, OtherBlocksKeepTheirElementNumbers) {
  BoxSpec s;
  s.name = "below";
  s.intervals = {2, 2, 1};
  Mesh m = generate_box(s);
  append(m, box4());
  BoxSpec t = s;
  t.name = "above";
  t.origin = {0, 0, 2};
  append(m, generate_box(t));
  const Mesh before = m;
  split_surface_layers(m, {"cube", "cube_zmin", 1, "skin"});
  ASSERT_EQ(m.blocks.size(), 4u);
  EXPECT_EQ(m.blocks[0].name, "below");
  EXPECT_EQ(m.blocks[1].name, "cube");
  EXPECT_EQ(m.blocks[1].first_element, 4);
  EXPECT_EQ(m.blocks[1].element_count, 48);
  EXPECT_EQ(m.blocks[2].name, "skin");
  EXPECT_EQ(m.blocks[2].first_element, 52);
  EXPECT_EQ(m.blocks[2].element_count, 16);
  EXPECT_EQ(m.blocks[3].name, "above");
  EXPECT_EQ(m.blocks[3].first_element, 68);
  for (int e : {0, 1, 2, 3, 68, 69, 70, 71})
    for (int a = 0; a < 8; ++a) EXPECT_EQ(m.connectivity[8 * e + a], before.connectivity[8 * e + a]);
  // Inside the split block: the rest keeps its relative order, the skin follows in its own.
  for (int k = 0; k < 48; ++k)
    for (int a = 0; a < 8; ++a) EXPECT_EQ(m.connectivity[8 * (4 + k) + a], before.connectivity[8 * (4 + 16 + k) + a]);
  validate(m, "split stack");
}

TEST(SurfaceLayers, TakingTheWholeBlockRemovesTheParent) {
  Mesh m = box4();
  const auto counts = split_surface_layers(m, {"cube", "cube_zmax", 4, "skin"});
  EXPECT_EQ(counts.skin, 64);
  EXPECT_EQ(counts.rest, 0);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "skin");
  EXPECT_EQ(m.blocks[0].element_count, 64);
  // More layers than the block has: the same, the layers stop when the block is used up.
  Mesh n = box4();
  EXPECT_EQ(split_surface_layers(n, {"cube", "cube_zmax", 10, "skin"}).skin, 64);
  EXPECT_EQ(n.connectivity, m.connectivity);
}

TEST(SurfaceLayers, SurfaceOffTheBlockTakesNothingAndIsAnError) {
  BoxSpec s;
  s.name = "far";
  s.origin = {5, 0, 0};
  Mesh m = box4();
  append(m, generate_box(s));
  const Mesh before = m;
  EXPECT_THROW(split_surface_layers(m, {"cube", "far_zmax", 1, "skin"}), MeshError);
  EXPECT_EQ(m.connectivity, before.connectivity);
  EXPECT_EQ(m.blocks.size(), before.blocks.size());
}

TEST(SurfaceLayers, Errors) {
  Mesh m = box4();
  auto message = [&](const SurfaceLayerSplit& s) {
    try {
      split_surface_layers(m, s);
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({"nope", "cube_zmax", 1, "skin"}).find("block 'nope' is not in the mesh"), std::string::npos);
  EXPECT_NE(message({"cube", "nope", 1, "skin"}).find("no side set or node set 'nope'"), std::string::npos);
  EXPECT_NE(message({"cube", "cube_zmax", 0, "skin"}).find("layers = 0"), std::string::npos);
  EXPECT_NE(message({"cube", "cube_zmax", 1, "cube"}).find("already has a block"), std::string::npos);
  EXPECT_EQ(m.blocks.size(), 1u);
}

}  // namespace
}  // namespace tribex::mesh
