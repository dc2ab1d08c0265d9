// SPDX-License-Identifier: MIT
// mesh/generated_plan.hpp in one process (label unit, so the sanitizer build runs it; the same checks per
// rank under mpiexec: tests/parallel_unit/mpi/generated_slab_test.cpp): the elements built from a plan
// are the serial generator's, restricted to them, for contiguous slabs and for a scattered list (a
// rank's part after the partition), on a graded box, a box + asperity appended as a deck composes them,
// and a quarter coated asperity with an apex position; the mesh's SHA-256 input (node_coordinates,
// element_nodes) is the serial arrays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

#include "mesh/asperity.hpp"
#include "mesh/box.hpp"
#include "mesh/generated_plan.hpp"
#include "mesh/mesh_error.hpp"
#include "tests/support/mpi_hertz_asperity.hpp"

namespace tribex::mesh {
namespace {

struct Pair {
  Mesh whole;
  GeneratedPlan plan;
};

Pair graded_box() {
  BoxSpec b;
  b.name = "slab";
  b.origin = {-1e-9, 2e-9, 0.5e-9};
  b.size = {9e-9, 4e-9, 7e-9};
  b.intervals = {5, 3, 6};
  b.grade_toward = "xmin";
  b.grading_ratio = 1.4;
  return {generate_box(b), plan_box(b)};
}

Pair box_and_asperity() {
  BoxSpec b;
  b.name = "anvil";
  b.size = {3e-9, 3e-9, 2e-9};
  b.intervals = {3, 3, 2};
  Pair p;
  add_box(p.whole, b);
  append(p.whole, generate_asperity(test::mpi_hertz_asperity()));
  append_plan(p.plan, plan_box(b));
  append_plan(p.plan, plan_asperity(test::mpi_hertz_asperity()));
  return p;
}

Pair quarter_coated() {
  AsperitySpec a = test::mpi_hertz_asperity();
  a.quarter = true;
  a.coating_thickness = 2e-9;
  a.coating_layers = 4;
  a.place_apex = true;
  a.apex = {1e-9, 1e-9, 5e-9};
  return {generate_asperity(a), plan_asperity(a)};
}

// The serial mesh restricted to `elements` (ascending), as generate_elements promises it.
void expect_restriction(const Pair& p, const std::vector<int>& elements) {
  std::vector<int> global_node;
  const Mesh got = generate_elements(p.plan, elements, global_node);
  std::vector<int> nodes;
  for (int e : elements)
    for (int a = 0; a < 8; ++a) nodes.push_back(p.whole.connectivity[8 * static_cast<std::size_t>(e) + a]);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  ASSERT_EQ(global_node, nodes);
  const auto local = [&](int n) { return static_cast<int>(std::lower_bound(nodes.begin(), nodes.end(), n) - nodes.begin()); };
  for (std::size_t l = 0; l < nodes.size(); ++l)
    for (int i = 0; i < 3; ++i) {
      const double want = p.whole.coordinates[3 * static_cast<std::size_t>(nodes[l]) + i];
      ASSERT_EQ(std::memcmp(&got.coordinates[3 * l + i], &want, sizeof(double)), 0) << "node " << nodes[l];
    }
  for (std::size_t k = 0; k < elements.size(); ++k)
    for (int a = 0; a < 8; ++a)
      ASSERT_EQ(got.connectivity[8 * k + a], local(p.whole.connectivity[8 * static_cast<std::size_t>(elements[k]) + a]));
  ASSERT_EQ(got.node_sets.size(), p.whole.node_sets.size());
  for (const auto& [name, set] : p.whole.node_sets) {
    std::vector<int> want;
    for (int n : set)
      if (std::binary_search(nodes.begin(), nodes.end(), n)) want.push_back(local(n));
    EXPECT_EQ(got.node_sets.at(name), want) << name;
  }
  ASSERT_EQ(got.side_sets.size(), p.whole.side_sets.size());
  for (const auto& [name, sides] : p.whole.side_sets) {
    std::vector<Side> want;
    for (const Side& s : sides)
      if (const auto at = std::lower_bound(elements.begin(), elements.end(), s.element);
          at != elements.end() && *at == s.element)
        want.push_back({static_cast<int>(at - elements.begin()), s.face});
    EXPECT_EQ(got.side_sets.at(name), want) << name;
  }
  ASSERT_EQ(got.blocks.size(), p.whole.blocks.size());
  for (std::size_t b = 0; b < got.blocks.size(); ++b) {
    const Block& w = p.whole.blocks[b];
    const auto first = std::lower_bound(elements.begin(), elements.end(), w.first_element);
    const auto last = std::lower_bound(first, elements.end(), w.first_element + w.element_count);
    EXPECT_EQ(got.blocks[b].name, w.name);
    EXPECT_EQ(got.blocks[b].first_element, static_cast<int>(first - elements.begin()));
    EXPECT_EQ(got.blocks[b].element_count, static_cast<int>(last - first));
  }
}

void expect_plan_is_the_mesh(const Pair& p) {
  ASSERT_EQ(p.plan.node_count, p.whole.node_count());
  ASSERT_EQ(p.plan.element_count, p.whole.element_count());
  const int ne = p.whole.element_count();
  for (int slabs : {1, 2, 5}) {  // contiguous slabs, uneven
    for (int s = 0; s < slabs; ++s) {
      std::vector<int> elements(static_cast<std::size_t>(ne * (s + 1) / slabs - ne * s / slabs));
      std::iota(elements.begin(), elements.end(), ne * s / slabs);
      expect_restriction(p, elements);
    }
  }
  std::vector<int> scattered;  // every third element and the last: a part after the partition
  for (int e = 0; e < ne; e += 3) scattered.push_back(e);
  if (scattered.back() != ne - 1) scattered.push_back(ne - 1);
  expect_restriction(p, scattered);
  const std::vector<double> x = node_coordinates(p.plan, 0, p.plan.node_count);
  EXPECT_EQ(std::memcmp(x.data(), p.whole.coordinates.data(), x.size() * sizeof(double)), 0);
  EXPECT_EQ(element_nodes(p.plan, 0, ne), p.whole.connectivity);
}

TEST(GeneratedPlan, GradedBoxIsTheSerialBox) { expect_plan_is_the_mesh(graded_box()); }

TEST(GeneratedPlan, BoxAndAsperityAreTheSerialMesh) { expect_plan_is_the_mesh(box_and_asperity()); }

TEST(GeneratedPlan, QuarterCoatedAsperityIsTheSerialMesh) { expect_plan_is_the_mesh(quarter_coated()); }

TEST(GeneratedPlan, NodesOfAGridAndSetSizes) {
  const Pair p = box_and_asperity();
  EXPECT_EQ(grid_of_node(p.plan, 0), 0);
  EXPECT_EQ(grid_of_node(p.plan, p.plan.node_count - 1), 2);  // anvil, substrate, tip
  for (const auto& [name, size] : p.plan.node_set_sizes())
    EXPECT_EQ(size, static_cast<int>(p.whole.node_sets.at(name).size())) << name;
  EXPECT_EQ(p.plan.node_set_ranges.at("anvil_all")[1], 4 * 4 * 3);
}

TEST(GeneratedPlan, BadSpecsFailAsTheGenerators) {
  BoxSpec b;
  b.intervals = {0, 1, 1};
  EXPECT_THROW(plan_box(b), MeshError);
  AsperitySpec a = test::mpi_hertz_asperity();
  a.tip_width = 60e-9;  // corners outside the sphere
  EXPECT_THROW(plan_asperity(a), MeshError);
  GeneratedPlan twice = plan_box(BoxSpec{});
  EXPECT_THROW(append_plan(twice, plan_box(BoxSpec{})), MeshError);  // a block name in both
}

}  // namespace
}  // namespace tribex::mesh
