// SPDX-License-Identifier: MIT
// `begin prescribed force` (load control): a total force on a node set, equal shares per node.
// One elastic hex8 on rollers (x = 0, y = 0, z = 0 faces) with the top face's four nodes pulled
// down by F: uniaxial stress, so the static top displacement is exactly -F L / (E A) and the base
// reaction is +F; mass damping brings the block to rest; the energy balance counts the load's work.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/errors.hpp"
#include "solver/integrators/central_difference.hpp"
#include "solver/model.hpp"
#include "support.hpp"
#include "tests/support/setup_errors.hpp"

namespace tribex {
namespace {

TEST(PrescribedForce, UniaxialBlockReachesTheStaticSolution) {
  const double L = 10e-9, E = 160e9, F = 100e-9;  // 100 nN on 100 nm^2: 1 GPa
  auto deck = test::box_deck(1, L, "elastic", inputs::ElementFormulation::mean_quadrature, E, 0.22,
                             2330.0);
  // No bulk viscosity: its ledger entry is approximate to O(dt^2) per step (solver/README.md), and
  // this test checks the load's work, which the scheme's pairing makes exact.
  deck.sections[0].linear_bulk_viscosity = 0.0;
  deck.sections[0].quadratic_bulk_viscosity = 0.0;
  using C = inputs::Component;
  auto& region = deck.procedure.region;
  region.fixed_displacements.push_back({"b_xmin", {C::x}, {}});
  region.fixed_displacements.push_back({"b_ymin", {C::y}, {}});
  region.fixed_displacements.push_back({"b_zmin", {C::z}, {}});
  // F(t): ramp over 20 ps, then held; scale -1: pulling down (compression).
  deck.functions.push_back({"load", {0.0, 20e-12, 1.0}, {0.0, F, F}, {}});
  region.prescribed_forces.push_back({"b_zmax", C::z, "load", -1.0, {}, {}});
  region.mass_damping_coefficient = 2e12;  // 1/s, about critical for the block's axial mode
  deck.procedure.time_control.termination_time = 200e-12;
  solver::Model model = solver::build_model(deck);
  ASSERT_EQ(model.nodal_forces.size(), 1u);
  ASSERT_EQ(model.nodal_forces[0].dof.size(), 4u);
  EXPECT_DOUBLE_EQ(model.nodal_forces[0].scale, -0.25);
  solver::CentralDifference cd(model, deck.procedure.time_control);
  cd.init();
  // Energy balance once the load has done work (the first steps compare round-off with ~0).
  double max_error = 0.0;
  cd.run([&] {
    if (cd.time() > 5e-12) max_error = std::max(max_error, cd.energies().relative_error());
  });
  double base = 0.0, top = 0.0;
  for (int node : model.mesh.node_sets.at("b_zmin")) base += cd.reaction()[3 * node + 2];
  for (int node : model.mesh.node_sets.at("b_zmax")) top += cd.displacement()[3 * node + 2] / 4.0;
  const double expected = -F * L / (E * L * L);
  std::printf("top displacement %.6g m (exact %.6g m), base reaction %.6g N, max energy error %.2e\n", top, expected, base,
              max_error);
  EXPECT_NEAR(top, expected, 1e-4 * std::abs(expected));
  EXPECT_NEAR(base, F, 1e-4 * F);
  // Without the load's work in the ledger the error would be ~1 (it is all the energy put in);
  // measured 6e-6, left by the mass-damping term while the load ramps.
  EXPECT_LT(max_error, 2e-5);
}

TEST(PrescribedForce, RefusesAConstrainedComponent) {
  auto deck = test::box_deck(1, 10e-9, "elastic", inputs::ElementFormulation::mean_quadrature);
  using C = inputs::Component;
  deck.procedure.region.fixed_displacements.push_back({"b_zmax", {C::z}, {}});
  deck.functions.push_back({"load", {0.0, 1.0}, {0.0, 1.0}, {}});
  deck.procedure.region.prescribed_forces.push_back({"b_zmax", C::z, "load", 1.0, {}, {}});
  const std::string msg = test::setup_error_of([&] { solver::build_model(deck); });
  EXPECT_NE(msg.find("is constrained at"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tribex
