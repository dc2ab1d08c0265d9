// SPDX-License-Identifier: MIT
// Patch test (docs/theory.md 2.2 verification handle): a 2x2x2 hex mesh with its interior node moved
// to a distorted position, driven by a linear displacement field u = eps0 x, must return the
// uniform stress C:eps0 in every element to 1e-10 relative, zero net force on the interior node,
// and zero hourglass energy - for both element formulations and both materials.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/box.hpp"
#include "solver/model.hpp"
#include "support.hpp"
#include "solver/hex8/internal_forces.hpp"

using namespace tribex;

namespace {

struct PatchCase {
  inputs::MaterialModel material;
  inputs::ElementFormulation formulation;
};

class PatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(PatchTest, LinearFieldGivesUniformStress) {
  const auto [material, formulation] = GetParam();
  const double E = 160e9, nu = 0.22;
  auto deck = test::box_deck(2, 1e-9, material, formulation, E, nu, 2330.0);
  mesh::BoxSpec spec;
  spec.name = "b";
  spec.size = {1e-9, 1e-9, 1e-9};
  spec.intervals = {2, 2, 2};
  mesh::Mesh mesh = mesh::generate_box(spec);
  const int centre = 13;  // node (1,1,1) of the 3x3x3 node grid
  ASSERT_NEAR(mesh.coordinates[3 * centre], 0.5e-9, 1e-20);
  mesh.coordinates[3 * centre + 0] += 0.11e-9;
  mesh.coordinates[3 * centre + 1] -= 0.07e-9;
  mesh.coordinates[3 * centre + 2] += 0.13e-9;
  solver::Model model = solver::build_model(deck, mesh);

  // Small general strain (uniaxial part plus shear) so that H = eps0 (symmetric).
  const double eps[9] = {1e-3, 2e-4, -1e-4, 2e-4, -3e-4, 5e-5, -1e-4, 5e-5, 4e-4};
  std::vector<double> u(3 * mesh.node_count()), v(3 * mesh.node_count(), 0.0), f(3 * mesh.node_count(), 0.0);
  for (int n = 0; n < mesh.node_count(); ++n)
    for (int i = 0; i < 3; ++i) {
      u[3 * n + i] = 0.0;
      for (int j = 0; j < 3; ++j) u[3 * n + i] += eps[3 * i + j] * mesh.coordinates[3 * n + j];
    }
  auto& blk = model.blocks[0];
  const auto totals = solver::add_internal_forces(blk, mesh.connectivity.data(), mesh.coordinates.data(), u.data(), v.data(), f.data(), 0.0, true);

  // Expected stress: linear elastic C:eps; neo-Hookean Cauchy stress of F = I + eps (uniform).
  double expected[6];
  const double no_plastic_strain[7] = {};  // elastic cases: a stateful model's state stays zero
  std::visit([&](const auto& mat) { materials::point_cauchy_stress(mat, eps, no_plastic_strain, expected); }, blk.material);
  const double lambda = materials::lame_lambda(E, nu), mu = materials::lame_mu(E, nu);
  if (material == "elastic") {
    const double tr = eps[0] + eps[4] + eps[8];
    EXPECT_NEAR(expected[0], lambda * tr + 2 * mu * eps[0], 1e-6);
    EXPECT_NEAR(expected[3], 2 * mu * eps[1], 1e-6);
  }
  const double scale = std::abs(expected[0]);
  for (int e = 0; e < blk.count; ++e)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(blk.stress[6 * e + k], expected[k], 1e-10 * scale) << "element " << e << " component " << k;
  const double fscale = scale * 1e-18;  // stress x face area
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[3 * centre + i], 0.0, 1e-10 * fscale) << "interior node force";
  EXPECT_NEAR(totals.hourglass_energy, 0.0, 1e-12 * totals.strain_energy);
}

INSTANTIATE_TEST_SUITE_P(
    AllFormulations, PatchTest,
    ::testing::Values(PatchCase{"elastic", inputs::ElementFormulation::mean_quadrature},
                      PatchCase{"elastic", inputs::ElementFormulation::fully_integrated},
                      PatchCase{"neo_hookean", inputs::ElementFormulation::mean_quadrature},
                      PatchCase{"neo_hookean", inputs::ElementFormulation::fully_integrated}),
    [](const ::testing::TestParamInfo<PatchCase>& p) {
      return std::string(p.param.material == "elastic" ? "Elastic" : "NeoHookean") +
             (p.param.formulation == inputs::ElementFormulation::mean_quadrature ? "MeanQuadrature" : "FullyIntegrated");
    });

}  // namespace
