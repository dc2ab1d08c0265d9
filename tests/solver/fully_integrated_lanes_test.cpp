// SPDX-License-Identifier: MIT
// The fully integrated kernel runs elements two per SSE register (materials/lanes.hpp). An
// element's forces, energy and stress must not depend on whether it ran in a pair or alone (so
// results do not depend on the partition or the block size): each element of a distorted 2x2x2
// box, run as a block of its own, must give bitwise what it gives inside the block of 8. And an
// inverted element in the second lane of a pair must be the one reported.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/box.hpp"
#include "solver/model.hpp"
#include "support.hpp"
#include "solver/hex8/internal_forces.hpp"

using namespace tribex;

namespace {

struct Box {
  mesh::Mesh mesh;
  solver::Model model;
};

Box distorted_box(inputs::MaterialModel material) {
  auto deck = test::box_deck(2, 1e-9, material, inputs::ElementFormulation::fully_integrated, 160e9, 0.22, 2330.0);
  mesh::BoxSpec spec;
  spec.name = "b";
  spec.size = {1e-9, 1e-9, 1e-9};
  spec.intervals = {2, 2, 2};
  Box box{mesh::generate_box(spec), {}};
  for (int n = 0; n < box.mesh.node_count(); ++n)
    for (int i = 0; i < 3; ++i) box.mesh.coordinates[3 * n + i] += 0.04e-9 * std::sin(1.3 * n + 2.1 * i);
  box.model = solver::build_model(deck, box.mesh);
  return box;
}

// Element e of the block as a block of its own.
solver::ElementBlock single_element(const solver::ElementBlock& blk, int e) {
  solver::ElementBlock one = blk;
  one.first_element = blk.first_element + e;
  one.count = 1;
  auto slice = [&](std::vector<double>& a, std::size_t stride) {
    a.assign(a.begin() + static_cast<std::ptrdiff_t>(stride * e), a.begin() + static_cast<std::ptrdiff_t>(stride * (e + 1)));
  };
  const int element[1] = {e};
  one.inv_jacobian = solver::select_interleaved(blk.inv_jacobian, element, 72);
  one.wdetJ = solver::select_interleaved(blk.wdetJ, element, 8);
  slice(one.B0, 24);
  slice(one.volume0, 1);
  slice(one.length0, 1);
  slice(one.stress, 6);
  return one;
}

class LanesTest : public ::testing::TestWithParam<inputs::MaterialModel> {};

TEST_P(LanesTest, PairsAndLoneElementsGiveTheSameForces) {
  Box box = distorted_box(GetParam());
  const int nodes = box.mesh.node_count();
  std::vector<double> u(3 * nodes), v(3 * nodes), f_block(3 * nodes, 0.0), f_single(3 * nodes, 0.0);
  for (int k = 0; k < 3 * nodes; ++k) {
    u[k] = 2e-11 * std::sin(0.7 * k);   // strains of a few per cent, not linear
    v[k] = 30.0 * std::cos(1.1 * k);    // compression and expansion: both bulk-viscosity branches
  }
  auto& blk = box.model.blocks[0];
  ASSERT_EQ(blk.count, 8);
  const int* conn = box.mesh.connectivity.data();
  const auto block_totals = solver::add_internal_forces(blk, conn, u.data(), v.data(), f_block.data(), 0.0, true);
  double energy = 0.0, power = 0.0;
  for (int e = 0; e < blk.count; ++e) {
    solver::ElementBlock one = single_element(blk, e);
    const auto t = solver::add_internal_forces(one, conn, u.data(), v.data(), f_single.data(), 0.0, true);
    energy += t.strain_energy;
    power += t.viscous_power;
    for (int k = 0; k < 6; ++k) EXPECT_EQ(one.stress[k], blk.stress[6 * e + k]) << "element " << e;
  }
  for (int k = 0; k < 3 * nodes; ++k) EXPECT_EQ(f_single[k], f_block[k]) << "force component " << k;
  EXPECT_EQ(energy, block_totals.strain_energy);
  EXPECT_EQ(power, block_totals.viscous_power);
  EXPECT_GT(block_totals.strain_energy, 0.0);
  EXPECT_EQ(block_totals.first_inverted, -1);
}

INSTANTIATE_TEST_SUITE_P(BothMaterials, LanesTest,
                         ::testing::Values("elastic", "neo_hookean"),
                         [](const ::testing::TestParamInfo<inputs::MaterialModel>& p) {
                           return std::string(p.param == "elastic" ? "Elastic" : "NeoHookean");
                         });

TEST(FullyIntegratedLanes, InvertedElementInTheSecondLaneIsReported) {
  Box box = distorted_box("neo_hookean");
  const int nodes = box.mesh.node_count();
  std::vector<double> u(3 * nodes, 0.0), v(3 * nodes, 0.0), f(3 * nodes, 0.0);
  // The (+,+,+) corner node belongs to element 7 only (lane 1 of the fourth pair): push it
  // through the element, to beyond the opposite corner.
  int corner = 0;
  for (int n = 1; n < nodes; ++n)
    if (box.mesh.coordinates[3 * n] + box.mesh.coordinates[3 * n + 1] + box.mesh.coordinates[3 * n + 2] >
        box.mesh.coordinates[3 * corner] + box.mesh.coordinates[3 * corner + 1] + box.mesh.coordinates[3 * corner + 2])
      corner = n;
  for (int i = 0; i < 3; ++i) u[3 * corner + i] = -1.0e-9;
  const auto t = solver::add_internal_forces(box.model.blocks[0], box.mesh.connectivity.data(), u.data(), v.data(),
                                             f.data(), 0.0, false);
  EXPECT_EQ(t.first_inverted, 7);
  EXPECT_TRUE(std::isfinite(t.strain_energy));  // the inverted element adds nothing
}

}  // namespace
