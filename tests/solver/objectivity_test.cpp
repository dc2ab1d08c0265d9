// SPDX-License-Identifier: MIT
// Objectivity: a neo-Hookean block in large rigid rotation (u = (R - I) X, rotations up to 170
// degrees about a skew axis) has no spurious stress, force or hourglass energy: |sigma| < 1e-8 mu.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/model.hpp"
#include "support.hpp"
#include "solver/hex8/internal_forces.hpp"

using namespace tribex;

namespace {
void rotation(double angle, const double axis_in[3], double R[9]) {
  const double n = std::sqrt(axis_in[0] * axis_in[0] + axis_in[1] * axis_in[1] + axis_in[2] * axis_in[2]);
  const double a[3] = {axis_in[0] / n, axis_in[1] / n, axis_in[2] / n};
  const double c = std::cos(angle), s = std::sin(angle);
  const double K[9] = {0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double kk = 0.0;
      for (int k = 0; k < 3; ++k) kk += K[3 * i + k] * K[3 * k + j];
      R[3 * i + j] = (i == j) + s * K[3 * i + j] + (1 - c) * kk;  // Rodrigues
    }
}
}  // namespace

TEST(Objectivity, NeoHookeanRigidRotationIsStressFree) {
  for (auto formulation : {inputs::ElementFormulation::mean_quadrature, inputs::ElementFormulation::fully_integrated}) {
    auto deck = test::box_deck(3, 1e-8, "neo_hookean", formulation, 160e9, 0.22, 2330.0);
    solver::Model model = solver::build_model(deck);
    const auto& X = model.mesh.coordinates;
    const int nn = model.mesh.node_count();
    const double mu = materials::lame_mu(160e9, 0.22);
    const double axis[3] = {1.0, 2.0, -0.5};
    for (double degrees : {30.0, 90.0, 170.0}) {
      double R[9];
      rotation(degrees * M_PI / 180.0, axis, R);
      std::vector<double> u(3 * nn), v(3 * nn, 0.0), f(3 * nn, 0.0);
      for (int n = 0; n < nn; ++n)
        for (int i = 0; i < 3; ++i) {
          double rx = 0.0;
          for (int j = 0; j < 3; ++j) rx += R[3 * i + j] * X[3 * n + j];
          u[3 * n + i] = rx - X[3 * n + i];
        }
      auto& blk = model.blocks[0];
      const auto totals = solver::add_internal_forces(blk, model.mesh.connectivity.data(), X.data(), u.data(), v.data(), f.data(), 0.0, true);
      double smax = 0.0, fmax = 0.0;
      for (double s : blk.stress) smax = std::max(smax, std::abs(s));
      for (double x : f) fmax = std::max(fmax, std::abs(x));
      EXPECT_LT(smax, 1e-8 * mu) << degrees << " degrees";
      EXPECT_LT(fmax, 1e-8 * mu * 1e-18) << degrees << " degrees (force scale mu h^2)";
      EXPECT_LT(totals.hourglass_energy, 1e-8 * mu * 1e-24);
      EXPECT_LT(std::abs(totals.strain_energy), 1e-8 * mu * 1e-24);
    }
  }
}
