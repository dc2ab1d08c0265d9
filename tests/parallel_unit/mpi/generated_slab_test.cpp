// SPDX-License-Identifier: MIT
// Generated meshes built per rank (mesh/generated_plan.hpp, issue 57 scope 2), run under mpiexec at 1, 2
// and 4 ranks (tests/parallel_unit/CMakeLists.txt). Every rank builds the serial mesh (small here) as
// the reference and its plan, and checks that its slab of the even split (slab_offsets), built from
// the plan alone, is the serial mesh restricted to those elements (split_mesh under the slab
// partition): the same global element and node numbers, bitwise the same coordinates, the same
// connectivity, blocks, node sets and side sets (in the set's order) and whole-mesh set sizes; and that
// the slabs of all the ranks together hold every element once and every node. The same on 1, 3 and 7
// slabs on every rank, so that a one-rank run checks uneven splits too. Meshes: two boxes (one graded)
// and the asperity of tests/parallel/mpi_hertz.i appended, as build_mesh composes a deck's model; a
// quarter asperity with a coating, a paraboloid tip, a fine x range and an apex position (the symmetry
// sets, the coating block, the tip map and the translation); a tip alone.
#include <gtest/gtest.h>
#include <mpi.h>

#include <numeric>
#include <vector>

#include "mesh/asperity.hpp"
#include "mesh/box.hpp"
#include "mesh/generated_plan.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/element_slab.hpp"
#include "solver/parallel/mesh_part.hpp"
#include "tests/support/mesh_part_equal.hpp"
#include "tests/support/mpi_hertz_asperity.hpp"

namespace tribex {
namespace {

namespace par = solver::parallel;

struct Case {
  mesh::Mesh whole;
  mesh::GeneratedPlan plan;
};

Case boxes_and_asperity() {
  mesh::BoxSpec block;
  block.name = "block";
  block.size = {20e-9, 15e-9, 12e-9};
  block.intervals = {7, 5, 4};
  block.grade_toward = "zmax";
  block.grading_ratio = 1.3;
  mesh::BoxSpec indenter;
  indenter.name = "indenter";
  indenter.origin = {5e-9, 5e-9, 12e-9};
  indenter.size = {6e-9, 6e-9, 3e-9};
  indenter.intervals = {3, 3, 2};
  mesh::AsperitySpec a = test::mpi_hertz_asperity();
  a.place_apex = true;
  a.apex = {0.0, 0.0, 60e-9};
  Case c;
  mesh::add_box(c.whole, block);
  mesh::add_box(c.whole, indenter);
  mesh::append(c.whole, mesh::generate_asperity(a));
  mesh::append_plan(c.plan, mesh::plan_box(block));
  mesh::append_plan(c.plan, mesh::plan_box(indenter));
  mesh::append_plan(c.plan, mesh::plan_asperity(a));
  return c;
}

Case quarter_coated() {
  mesh::AsperitySpec a = test::mpi_hertz_asperity();
  a.quarter = true;
  a.coating_thickness = 2e-9;
  a.coating_layers = 3;
  a.paraboloid = true;
  a.fine_x_range = std::array<double, 2>{-6.4e-9, 12e-9};
  a.place_apex = true;
  a.apex = {3e-9, -2e-9, 1e-9};
  a.gap = 0.5e-9;
  return {mesh::generate_asperity(a), mesh::plan_asperity(a)};
}

Case tip_alone() {
  mesh::AsperitySpec a = test::mpi_hertz_asperity();
  a.tip_only = true;
  a.place_apex = true;
  a.apex = {1e-9, 2e-9, 3e-9};
  return {mesh::generate_asperity(a), mesh::plan_asperity(a)};
}

// Slab `r` of `slabs` from the plan against split_mesh of the serial mesh under the slab partition.
void expect_slab(const Case& c, int slabs, int r, std::vector<int>& covered) {
  const int ne = c.whole.element_count();
  const std::vector<int> offset = par::slab_offsets(ne, slabs);
  std::vector<int> part(static_cast<std::size_t>(ne));
  for (int s = 0; s < slabs; ++s) std::fill(part.begin() + offset[s], part.begin() + offset[s + 1], s);
  const par::MeshPart want = par::split_mesh(c.whole, part, par::node_holders(c.whole, part), r);
  std::vector<int> elements(static_cast<std::size_t>(offset[r + 1] - offset[r]));
  std::iota(elements.begin(), elements.end(), offset[r]);
  std::vector<int> global_node;
  const mesh::Mesh got = mesh::generate_elements(c.plan, elements, global_node);
  SCOPED_TRACE("slab " + std::to_string(r) + " of " + std::to_string(slabs));
  EXPECT_EQ(elements, want.global_element);
  EXPECT_EQ(global_node, want.global_node);
  test::expect_same_mesh(got, want.mesh);
  EXPECT_EQ(c.plan.node_set_sizes(), want.node_set_size);
  EXPECT_EQ(c.plan.side_set_sizes(), want.side_set_size);
  const std::vector<int> corners = mesh::element_nodes(c.plan, offset[r], offset[r + 1] - offset[r]);
  EXPECT_TRUE(std::equal(corners.begin(), corners.end(), c.whole.connectivity.begin() + 8 * offset[r]));
  for (int n : global_node) covered[static_cast<std::size_t>(n)] = 1;
}

void expect_slabs_are_the_mesh(const Case& c) {
  ASSERT_EQ(c.plan.node_count, c.whole.node_count());
  ASSERT_EQ(c.plan.element_count, c.whole.element_count());
  // Every slab of 1, 3 and 7 on this rank: the union holds every node.
  for (int slabs : {1, 3, 7}) {
    std::vector<int> covered(static_cast<std::size_t>(c.whole.node_count()), 0);
    for (int r = 0; r < slabs; ++r) expect_slab(c, slabs, r, covered);
    EXPECT_EQ(std::accumulate(covered.begin(), covered.end(), 0), c.whole.node_count());
  }
  // This rank's slab of the ranks' split; together (MPI_MAX) they hold every node.
  std::vector<int> covered(static_cast<std::size_t>(c.whole.node_count()), 0);
  expect_slab(c, par::size(), par::rank(), covered);
  MPI_Allreduce(MPI_IN_PLACE, covered.data(), static_cast<int>(covered.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(std::accumulate(covered.begin(), covered.end(), 0), c.whole.node_count());
}

TEST(GeneratedSlab, BoxesAndAsperityAreTheSerialMesh) { expect_slabs_are_the_mesh(boxes_and_asperity()); }

TEST(GeneratedSlab, QuarterCoatedAsperityIsTheSerialMesh) { expect_slabs_are_the_mesh(quarter_coated()); }

TEST(GeneratedSlab, TipAloneIsTheSerialMesh) { expect_slabs_are_the_mesh(tip_alone()); }

TEST(GeneratedSlab, SetsOfTheSerialMesh) {
  // The plan's sets are the serial mesh's by name (the surface sets whole, NAME_all as a node range).
  const Case c = quarter_coated();
  for (const auto& [name, size] : c.plan.node_set_sizes()) {
    ASSERT_TRUE(c.whole.node_sets.count(name)) << name;
    EXPECT_EQ(size, static_cast<int>(c.whole.node_sets.at(name).size())) << name;
  }
  EXPECT_EQ(c.plan.node_set_sizes().size(), c.whole.node_sets.size());
  EXPECT_EQ(c.plan.side_sets, c.whole.side_sets);
  EXPECT_TRUE(c.plan.node_set_ranges.count("substrate_all"));
  EXPECT_EQ(c.plan.node_sets.at("symmetry_x"), c.whole.node_sets.at("symmetry_x"));
}

}  // namespace
}  // namespace tribex
