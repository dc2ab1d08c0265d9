// SPDX-License-Identifier: MIT
// The element kernels run elements eight per AVX-512 register, four per AVX2 register, two per SSE
// register, or alone (materials/lanes.hpp). An element's forces, energy and stress must not depend
// on the lane it ran in or on the lane width (so results do not depend on the partition, the block
// size or the CPU): each element of a distorted 3x3x3 box (27 elements: six groups of four, a pair
// and one alone; at eight lanes three groups of eight, the pair and the one), run as a block of its
// own, must give bitwise what it gives inside the block, at lane widths 2, 4 and 8, for both
// formulations and both hyperelastic materials; and an inverted element in a later lane must be the
// one reported.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "mesh/box.hpp"
#include "solver/model.hpp"
#include "solver/stable_time_step.hpp"
#include "support.hpp"
#include "solver/hex8/internal_forces.hpp"

using namespace tribex;

namespace {

struct Box {
  mesh::Mesh mesh;
  solver::Model model;
};

Box distorted_box(inputs::MaterialModel material, inputs::ElementFormulation formulation, int n = 3) {
  auto deck = test::box_deck(n, 1e-9, material, formulation, 160e9, 0.22, 2330.0);
  deck.sections[0].hourglass_viscosity = 0.1;  // both hourglass terms of the mean-quadrature kernel
  mesh::BoxSpec spec;
  spec.name = "b";
  spec.size = {1e-9, 1e-9, 1e-9};
  spec.intervals = {n, n, n};
  Box box{mesh::generate_box(spec), {}};
  for (int node = 0; node < box.mesh.node_count(); ++node)
    for (int i = 0; i < 3; ++i) box.mesh.coordinates[3 * node + i] += 0.04e-9 / (n / 2.0) * std::sin(1.3 * node + 2.1 * i);
  box.model = solver::build_model(deck, box.mesh);
  return box;
}

// Element e of the block as a block of its own.
solver::ElementBlock single_element(const solver::ElementBlock& blk, int e) {
  solver::ElementBlock one = blk;
  one.first_element = blk.first_element + e;
  one.count = 1;
  auto slice = [&](std::vector<double>& a, std::size_t stride) {
    if (a.empty()) return;
    a.assign(a.begin() + static_cast<std::ptrdiff_t>(stride * e), a.begin() + static_cast<std::ptrdiff_t>(stride * (e + 1)));
  };
  const int element[1] = {e};
  one.B0 = solver::select_interleaved(blk.B0, element, 24);
  one.hg_coefficients = solver::select_interleaved(blk.hg_coefficients, element, 12);
  one.wdetJ = solver::select_interleaved(blk.wdetJ, element, 8);
  slice(one.volume0, 1);
  slice(one.length0, 1);
  slice(one.hg_k, 1);
  slice(one.hg_c, 1);
  slice(one.stress, 6);
  return one;
}

struct PassResult {
  std::vector<double> force, stress;
  solver::ElementPassTotals totals;
};

PassResult run_pass(solver::ElementBlock blk, const mesh::Mesh& mesh, const std::vector<double>& u,
                    const std::vector<double>& v, int lanes, solver::KernelIsa isa = solver::KernelIsa::avx512) {
  solver::set_element_lane_width(lanes);
  solver::limit_element_isa(isa);
  PassResult r{std::vector<double>(u.size(), 0.0), {}, {}};
  r.totals = solver::add_internal_forces(blk, mesh.connectivity.data(), mesh.coordinates.data(), u.data(), v.data(), r.force.data(), 0.0, true);
  r.stress = blk.stress;
  solver::set_element_lane_width(0);
  solver::limit_element_isa(solver::KernelIsa::avx512);
  return r;
}

using LaneCase = std::tuple<inputs::MaterialModel, inputs::ElementFormulation>;
class LanesTest : public ::testing::TestWithParam<LaneCase> {};

TEST_P(LanesTest, ElementsGiveBitwiseTheSameResultsAtEveryLaneWidthAndAlone) {
  const auto [material, formulation] = GetParam();
  Box box = distorted_box(material, formulation);
  const int nodes = box.mesh.node_count();
  std::vector<double> u(3 * nodes), v(3 * nodes);
  for (int k = 0; k < 3 * nodes; ++k) {
    u[k] = 2e-11 * std::sin(0.7 * k);   // strains of a few per cent, not linear: hourglass modes too
    v[k] = 30.0 * std::cos(1.1 * k);    // compression and expansion: both bulk-viscosity branches
  }
  const auto& blk = box.model.blocks[0];
  ASSERT_EQ(blk.count, 27);
  const PassResult two = run_pass(blk, box.mesh, u, v, 2);
  // four lanes with the CPU's best instruction set (AVX-512VL's 32 registers where it has them) and
  // with AVX2's 16
  const PassResult four = run_pass(blk, box.mesh, u, v, 4);
  const PassResult four_avx2 = run_pass(blk, box.mesh, u, v, 4, solver::KernelIsa::avx2);
  if (solver::element_lane_width() < 8) {
    GTEST_LOG_(INFO) << "this CPU has no AVX-512F with VL (width 8 ran as " << solver::element_lane_width() << ")"
                     << (solver::element_lane_width() < 4 ? " and no AVX2 (width 4 ran as 2)" : "");
  }
  // eight lanes: three groups of eight, then the pair and the lone element
  const PassResult eight = run_pass(blk, box.mesh, u, v, 8);
  for (const PassResult* wide : {&four, &four_avx2, &eight}) {
    for (int k = 0; k < 3 * nodes; ++k) EXPECT_EQ(two.force[k], wide->force[k]) << "force component " << k;
    for (std::size_t k = 0; k < two.stress.size(); ++k) EXPECT_EQ(two.stress[k], wide->stress[k]) << "stress " << k;
    EXPECT_EQ(two.totals.strain_energy, wide->totals.strain_energy);
    EXPECT_EQ(two.totals.hourglass_energy, wide->totals.hourglass_energy);
    EXPECT_EQ(two.totals.viscous_power, wide->totals.viscous_power);
  }

  std::vector<double> f_single(3 * nodes, 0.0);
  double energy = 0.0, hourglass = 0.0, power = 0.0;
  for (int e = 0; e < blk.count; ++e) {
    solver::ElementBlock one = single_element(blk, e);
    const auto t = solver::add_internal_forces(one, box.mesh.connectivity.data(), box.mesh.coordinates.data(), u.data(), v.data(), f_single.data(), 0.0, true);
    energy += t.strain_energy;
    hourglass += t.hourglass_energy;
    power += t.viscous_power;
    for (int k = 0; k < 6; ++k) EXPECT_EQ(one.stress[k], four.stress[6 * e + k]) << "element " << e;
  }
  for (int k = 0; k < 3 * nodes; ++k) EXPECT_EQ(f_single[k], four.force[k]) << "force component " << k;
  EXPECT_EQ(energy, four.totals.strain_energy);
  EXPECT_EQ(hourglass, four.totals.hourglass_energy);
  EXPECT_EQ(power, four.totals.viscous_power);
  EXPECT_GT(four.totals.strain_energy, 0.0);
  if (formulation == inputs::ElementFormulation::mean_quadrature) {
    EXPECT_GT(four.totals.hourglass_energy, 0.0);
  }
  EXPECT_EQ(four.totals.first_inverted, -1);
}

// The stable step folded into the force pass is bitwise compute_stable_time_step's, at every width.
TEST_P(LanesTest, FoldedStableStepIsTheSeparatePassBitwise) {
  const auto [material, formulation] = GetParam();
  Box box = distorted_box(material, formulation);
  const int nodes = box.mesh.node_count();
  std::vector<double> u(3 * nodes), v(3 * nodes, 0.0);
  for (int k = 0; k < 3 * nodes; ++k) u[k] = 4e-11 * std::sin(0.7 * k) + 1e-11 * std::cos(0.3 * k * k);
  const solver::StableStep separate = solver::compute_stable_time_step(box.model, u.data());
  ASSERT_GT(separate.dt, 0.0);
  ASSERT_EQ(separate.inverted_element, -1);
  for (const auto isa : {solver::KernelIsa::avx2, solver::KernelIsa::avx512})
    for (int lanes : {2, 4, 8}) {
      solver::set_element_lane_width(lanes);
      solver::limit_element_isa(isa);
      std::vector<double> f(3 * nodes, 0.0);
      const auto totals = solver::add_internal_forces(box.model.blocks[0], box.mesh.connectivity.data(),
                                                      box.mesh.coordinates.data(), u.data(), v.data(), f.data(), 0.0, false, true);
      EXPECT_EQ(totals.stable.dt, separate.dt) << lanes << " lanes, isa " << int(isa);
      EXPECT_EQ(totals.stable.controlling_element, separate.controlling_element) << lanes << " lanes, isa " << int(isa);
      EXPECT_EQ(totals.stable.inverted_element, -1);
    }
  solver::set_element_lane_width(0);
  solver::limit_element_isa(solver::KernelIsa::avx512);
}

INSTANTIATE_TEST_SUITE_P(
    MaterialsAndFormulations, LanesTest,
    ::testing::Combine(::testing::Values("elastic", "neo_hookean"),
                       ::testing::Values(inputs::ElementFormulation::mean_quadrature,
                                         inputs::ElementFormulation::fully_integrated)),
    [](const ::testing::TestParamInfo<LaneCase>& p) {
      return std::string(std::get<0>(p.param) == "elastic" ? "Elastic" : "NeoHookean") +
             (std::get<1>(p.param) == inputs::ElementFormulation::mean_quadrature ? "MeanQuadrature" : "FullyIntegrated");
    });

// 125 elements at eight lanes: 15 groups of eight, then the four-lane tail (the AVX-512 file's own
// double4 batch) and one alone; bitwise the two-lane pass, both formulations.
TEST(EightLanes, TailOfFourAndOneIsBitwiseTheTwoLanePass) {
  for (auto formulation : {inputs::ElementFormulation::mean_quadrature, inputs::ElementFormulation::fully_integrated}) {
    Box box = distorted_box("neo_hookean", formulation, 5);
    const int nodes = box.mesh.node_count();
    std::vector<double> u(3 * nodes), v(3 * nodes);
    for (int k = 0; k < 3 * nodes; ++k) {
      u[k] = 1e-11 * std::sin(0.7 * k);
      v[k] = 30.0 * std::cos(1.1 * k);
    }
    const auto& blk = box.model.blocks[0];
    ASSERT_EQ(blk.count, 125);
    const PassResult two = run_pass(blk, box.mesh, u, v, 2);
    const PassResult eight = run_pass(blk, box.mesh, u, v, 8);
    for (int k = 0; k < 3 * nodes; ++k) EXPECT_EQ(two.force[k], eight.force[k]) << "force component " << k;
    for (std::size_t k = 0; k < two.stress.size(); ++k) EXPECT_EQ(two.stress[k], eight.stress[k]) << "stress " << k;
    EXPECT_EQ(two.totals.strain_energy, eight.totals.strain_energy);
    EXPECT_EQ(two.totals.viscous_power, eight.totals.viscous_power);
    EXPECT_GT(two.totals.strain_energy, 0.0);
  }
}

TEST(FullyIntegratedLanes, InvertedElementInALaterLaneIsReported) {
  for (int lanes : {2, 4, 8}) {
    Box box = distorted_box("neo_hookean", inputs::ElementFormulation::fully_integrated, 2);
    const int nodes = box.mesh.node_count();
    std::vector<double> u(3 * nodes, 0.0), v(3 * nodes, 0.0);
    // The (+,+,+) corner node belongs to element 7 only (the last lane of a pair or of a group
    // of four): push it through the element, to beyond the opposite corner.
    int corner = 0;
    for (int n = 1; n < nodes; ++n)
      if (box.mesh.coordinates[3 * n] + box.mesh.coordinates[3 * n + 1] + box.mesh.coordinates[3 * n + 2] >
          box.mesh.coordinates[3 * corner] + box.mesh.coordinates[3 * corner + 1] + box.mesh.coordinates[3 * corner + 2])
        corner = n;
    for (int i = 0; i < 3; ++i) u[3 * corner + i] = -1.0e-9;
    const PassResult r = run_pass(box.model.blocks[0], box.mesh, u, v, lanes);
    EXPECT_EQ(r.totals.first_inverted, 7) << lanes << " lanes";
    EXPECT_TRUE(std::isfinite(r.totals.strain_energy));  // the inverted element adds nothing
  }
}

}  // namespace

#include "solver/hex8/geometry.hpp"
#include "solver/hex8/mean_quadrature.hpp"

namespace {

// The mean-quadrature kernel's add-and-subtract forms of Gamma x and Gamma^T r against the table
// of hourglass base vectors (exact: the values are small integers).
TEST(HourglassBase, SumsAndCombinationsMatchTheBaseVectors) {
  using solver::hex8::hourglass_base;
  const double x[8] = {3, -7, 11, 2, -5, 13, 17, -19};
  double g[4];
  solver::hex8::hourglass_base_sums(x, g);
  for (int a = 0; a < 4; ++a) {
    double expected = 0.0;
    for (int J = 0; J < 8; ++J) expected += hourglass_base[a][J] * x[J];
    EXPECT_EQ(g[a], expected) << "mode " << a;
  }
  const double r[4] = {2, -3, 5, 7};
  double f[8];
  solver::hex8::hourglass_base_combinations(r[0], r[1], r[2], r[3], f);
  for (int I = 0; I < 8; ++I) {
    double expected = 0.0;
    for (int a = 0; a < 4; ++a) expected += hourglass_base[a][I] * r[a];
    EXPECT_EQ(f[I], expected) << "node " << I;
  }
}

}  // namespace
