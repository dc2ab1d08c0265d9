// SPDX-License-Identifier: MIT
// The distributed set-up's pieces that need no mpiexec (issue 25 scope 1): the split of a mesh into
// the ranks' parts (parallel/mesh_part.hpp), the set-up messages' byte form, and build_model on a
// part, which on one rank must give the serial model bit for bit (the same sums in the same order).
// The parts at 2 and 4 ranks run under mpiexec in tests/parallel.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "inputs/diagnostics.hpp"
#include "mesh/box.hpp"
#include "solver/setup/contact_setup.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "solver/parallel/mesh_part.hpp"
#include "solver/parallel/partition.hpp"
#include "tests/support/mesh_part_equal.hpp"

using namespace tribex;
using solver::parallel::MeshPart;

namespace {

mesh::Mesh two_block_box() {
  mesh::BoxSpec lower, upper;
  lower.name = "lower";
  lower.intervals = {5, 4, 3};
  upper.name = "upper";
  upper.intervals = {5, 4, 2};
  upper.origin = {0.0, 0.0, 1.0};
  mesh::Mesh m = mesh::generate_box(lower);
  mesh::append(m, mesh::generate_box(upper));
  return m;
}

}  // namespace

TEST(SplitMesh, PartsHoldEveryElementOnceAndMapBackToTheWholeMesh) {
  const mesh::Mesh whole = two_block_box();
  const int ranks = 3;
  const std::vector<int> part = solver::parallel::partition_elements(whole, ranks);
  const auto holders = solver::parallel::node_holders(whole, part);
  std::vector<int> element_seen(static_cast<std::size_t>(whole.element_count()), 0);
  std::vector<int> owners(static_cast<std::size_t>(whole.node_count()), 0);
  std::map<std::string, std::multiset<int>> node_sets;
  std::map<std::string, std::multiset<std::pair<int, int>>> side_sets;
  std::vector<int> block_elements(whole.blocks.size(), 0);
  for (int r = 0; r < ranks; ++r) {
    const MeshPart p = solver::parallel::split_mesh(whole, part, holders, r);
    EXPECT_EQ(p.global_node_count, whole.node_count());
    EXPECT_EQ(p.global_element_count, whole.element_count());
    ASSERT_TRUE(std::is_sorted(p.global_node.begin(), p.global_node.end()));
    ASSERT_TRUE(std::is_sorted(p.global_element.begin(), p.global_element.end()));
    for (int l = 0; l < p.mesh.element_count(); ++l) {
      const int e = p.global_element[l];
      EXPECT_EQ(part[e], r);
      ++element_seen[e];
      for (int I = 0; I < 8; ++I)
        EXPECT_EQ(p.global_node[p.mesh.connectivity[8 * l + I]], whole.connectivity[8 * e + I]);
    }
    for (int l = 0; l < p.mesh.node_count(); ++l) {
      const int n = p.global_node[l];
      for (int i = 0; i < 3; ++i) EXPECT_EQ(p.mesh.coordinates[3 * l + i], whole.coordinates[3 * n + i]);
      const std::vector<int> mine(p.holder_rank.begin() + p.holder_offset[l], p.holder_rank.begin() + p.holder_offset[l + 1]);
      EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
      EXPECT_NE(std::find(mine.begin(), mine.end(), r), mine.end());
      owners[n] += mine.front() == r;  // the lowest holder owns the node
    }
    ASSERT_EQ(p.mesh.blocks.size(), whole.blocks.size());
    for (std::size_t b = 0; b < whole.blocks.size(); ++b) {
      EXPECT_EQ(p.mesh.blocks[b].name, whole.blocks[b].name);
      block_elements[b] += p.mesh.blocks[b].element_count;
      for (int k = 0; k < p.mesh.blocks[b].element_count; ++k) {
        const int e = p.global_element[p.mesh.blocks[b].first_element + k];
        EXPECT_GE(e, whole.blocks[b].first_element);
        EXPECT_LT(e, whole.blocks[b].first_element + whole.blocks[b].element_count);
      }
    }
    for (const auto& [name, nodes] : whole.node_sets) {
      EXPECT_EQ(p.node_set_size.at(name), static_cast<int>(nodes.size()));
      for (int l : p.mesh.node_sets.at(name)) node_sets[name].insert(p.global_node[l]);
    }
    for (const auto& [name, sides] : whole.side_sets) {
      EXPECT_EQ(p.side_set_size.at(name), static_cast<int>(sides.size()));
      for (const auto& s : p.mesh.side_sets.at(name)) side_sets[name].insert({p.global_element[s.element], s.face});
    }
  }
  for (int seen : element_seen) EXPECT_EQ(seen, 1);
  for (int owned : owners) EXPECT_EQ(owned, 1);
  for (std::size_t b = 0; b < whole.blocks.size(); ++b) EXPECT_EQ(block_elements[b], whole.blocks[b].element_count);
  for (const auto& [name, nodes] : whole.node_sets) {
    // every holder keeps the set's node, so each appears once per holder
    std::multiset<int> expected;
    for (int n : nodes)
      for (int k = 0; k < holders.count(n); ++k) expected.insert(n);
    EXPECT_EQ(node_sets[name], expected) << name;
  }
  for (const auto& [name, sides] : whole.side_sets) {
    std::multiset<std::pair<int, int>> expected;
    for (const auto& s : sides) expected.insert({s.element, s.face});
    EXPECT_EQ(side_sets[name], expected) << name;  // each side on exactly one rank, its element's
  }
}

TEST(SplitMesh, ANodeInNoElementIsRefusedBeforeAnyPartIsSent) {
  mesh::Mesh whole = two_block_box();
  for (int i = 0; i < 3; ++i) whole.coordinates.push_back(9.0);
  const std::vector<int> part(static_cast<std::size_t>(whole.element_count()), 0);
  try {
    solver::parallel::node_holders(whole, part);
    FAIL() << "expected SetupError";
  } catch (const solver::SetupError& e) {
    EXPECT_EQ(std::string(e.what()), "mesh node " + std::to_string(whole.node_count()) +
                                         " belongs to no element (zero mass); remove it from the mesh");
  }
}

TEST(SplitMesh, APartSurvivesItsMessage) {
  const mesh::Mesh whole = two_block_box();
  const std::vector<int> part = solver::parallel::partition_elements(whole, 2);
  const MeshPart p = solver::parallel::split_mesh(whole, part, solver::parallel::node_holders(whole, part), 1);
  const MeshPart back = solver::parallel::unpack_part(solver::parallel::pack_part(p));
  test::expect_same_part(back, p);
}

// build_model on a one-rank part (the parallel set-up's code: partial sums, the contact faces given
// and the surface masses summed from their owners) against the serial build_model: the same model bit for bit.
class BuildModelOnAPart : public ::testing::TestWithParam<const char*> {};

TEST_P(BuildModelOnAPart, EqualsTheSerialModelOnOneRank) {
  const inputs::Deck deck = inputs::parse_deck_file(std::string(TRIBEX_SOURCE_DIR) + "/" + GetParam());
  const solver::Model serial = solver::build_model(deck);
  const mesh::Mesh whole = solver::build_mesh(deck);
  const std::vector<int> part(static_cast<std::size_t>(whole.element_count()), 0);
  const auto holders = solver::parallel::node_holders(whole, part);
  const solver::ContactFaces faces =
      deck.procedure.region.contact ? solver::contact_faces(whole, *deck.procedure.region.contact) : solver::ContactFaces{};
  const solver::Model m = solver::build_model(deck, solver::parallel::split_mesh(whole, part, holders, 0), faces);
  EXPECT_EQ(m.mass, serial.mass);
  EXPECT_EQ(m.total_mass, serial.total_mass);
  EXPECT_EQ(m.initial_velocity, serial.initial_velocity);
  EXPECT_EQ(m.constraints.dof, serial.constraints.dof);
  EXPECT_EQ(m.constraints.scale, serial.constraints.scale);
  EXPECT_EQ(m.silent.node, serial.silent.node);
  EXPECT_EQ(m.silent.normal, serial.silent.normal);
  EXPECT_EQ(m.silent.c_normal, serial.silent.c_normal);
  EXPECT_EQ(m.silent.c_tangential, serial.silent.c_tangential);
  ASSERT_EQ(m.nodal_forces.size(), serial.nodal_forces.size());
  for (std::size_t k = 0; k < m.nodal_forces.size(); ++k) {
    EXPECT_EQ(m.nodal_forces[k].dof, serial.nodal_forces[k].dof);
    EXPECT_EQ(m.nodal_forces[k].scale, serial.nodal_forces[k].scale);
  }
  ASSERT_EQ(m.pressures.size(), serial.pressures.size());
  for (std::size_t k = 0; k < m.pressures.size(); ++k) EXPECT_EQ(m.pressures[k].face_nodes, serial.pressures[k].face_nodes);
  ASSERT_EQ(m.blocks.size(), serial.blocks.size());
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    EXPECT_EQ(m.blocks[b].B0, serial.blocks[b].B0);
    EXPECT_EQ(m.blocks[b].mass_scale, serial.blocks[b].mass_scale);
  }
  EXPECT_EQ(m.mass_scaling.added_mass, serial.mass_scaling.added_mass);
  EXPECT_EQ(m.mass_scaling.lines(), serial.mass_scaling.lines());
  EXPECT_EQ(m.preflight, serial.preflight);  // contact: the same interactions, gaps and penalty lines
  ASSERT_EQ(m.contact != nullptr, serial.contact != nullptr);
  if (m.contact) {
    ASSERT_EQ(m.contact->surfaces().size(), serial.contact->surfaces().size());
    for (std::size_t s = 0; s < m.contact->surfaces().size(); ++s)
      EXPECT_EQ(m.contact->surfaces()[s].face_count(), serial.contact->surfaces()[s].face_count());
    EXPECT_EQ(m.contact->surface_nodes(), serial.contact->surface_nodes());
    EXPECT_EQ(m.contact_global_node, serial.contact_global_node);
    EXPECT_FALSE(m.contact_global_node.empty());
  }
}

INSTANTIATE_TEST_SUITE_P(Decks, BuildModelOnAPart,
                         ::testing::Values("verification/hertz/hertz_coarse_mass_scaled.i", "tests/parallel/mpi_loads.i",
                                           "tests/parallel/mpi_wave.i", "verification/dmt/dmt_coarse.i"));
