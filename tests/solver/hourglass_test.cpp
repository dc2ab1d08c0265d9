// SPDX-License-Identifier: MIT
// A single mean-quadrature element driven in the pure hourglass mode Gamma_1 (docs/theory.md 2.2): the
// stiffness form returns a non-zero restoring force, and the stored hourglass energy equals the
// work done by the driver (trapezoidal rule, exact for the linear force) to 1e-10.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/model.hpp"
#include "support.hpp"
#include "solver/hex8/internal_forces.hpp"

using namespace tribex;

TEST(Hourglass, PureModeStoresTheDriverWork) {
  auto deck = test::box_deck(1, 1e-9, "elastic", inputs::ElementFormulation::mean_quadrature,
                             160e9, 0.22, 2330.0);
  solver::Model model = solver::build_model(deck);
  auto& blk = model.blocks[0];
  ASSERT_DOUBLE_EQ(blk.hourglass_stiffness, 0.05);
  const double Gamma1[8] = {1, 1, -1, -1, -1, -1, 1, 1};
  const int nn = model.mesh.node_count();
  std::vector<double> u(3 * nn, 0.0), v(3 * nn, 0.0), f(3 * nn, 0.0), f_prev(3 * nn, 0.0);
  const double amplitude = 1e-12;  // m
  const int steps = 50;
  double work = 0.0, hourglass = 0.0;
  const int* conn = model.mesh.connectivity.data();
  for (int s = 1; s <= steps; ++s) {
    std::vector<double> du(3 * nn, 0.0);
    for (int I = 0; I < 8; ++I) du[3 * conn[I]] = amplitude / steps * Gamma1[I];  // x motion in mode Gamma_1
    for (int k = 0; k < 3 * nn; ++k) u[k] += du[k];
    std::fill(f.begin(), f.end(), 0.0);
    const auto totals = solver::add_internal_forces(blk, conn, model.mesh.coordinates.data(), u.data(), v.data(), f.data(), 0.0, false);
    // Work of the driver = -(internal force) . du, trapezoidal in force.
    for (int k = 0; k < 3 * nn; ++k) work += -0.5 * (f[k] + f_prev[k]) * du[k];
    f_prev = f;
    hourglass = totals.hourglass_energy;
    EXPECT_NEAR(totals.strain_energy, 0.0, 1e-12 * totals.hourglass_energy) << "pure hourglass mode carries no strain";
  }
  double fmax = 0.0;
  for (double x : f) fmax = std::max(fmax, std::abs(x));
  EXPECT_GT(fmax, 0.0) << "restoring force";
  // Restoring: the force opposes the mode.
  EXPECT_LT(f[3 * conn[0]] * Gamma1[0], 0.0);
  EXPECT_GT(hourglass, 0.0);
  EXPECT_NEAR(hourglass, work, 1e-10 * work);
}
