// SPDX-License-Identifier: MIT
// The penalty of a mass-scaled run (docs/theory.md 1.4.1, ContactManager::set_unscaled_penalty_reference):
// k_p = min(s m_eff,0 / dt_0^2, s m_eff / dt^2): the unscaled deck's stiffness, never above the unscaled
// run's ratio k dt^2 / m_eff = s on the scaled masses and step. One slave node 0.05 nm below the centre of a master face (N_a = 1/4, so
// 1/m_M = 4 (1/4)^2 / m = 1/(4 m) and m_eff = m 4m / 5m = 0.8 m for equal masses m).
#include <gtest/gtest.h>

#include <vector>

#include "support.hpp"

namespace tribex::contact {
namespace {

using test::nm;

struct Penetration {
  mesh::Mesh mesh = test::two_flats({.gap = 1 * nm});
  int node = -1;
  double depth = 0.05 * nm;
  Penetration() {
    const double pitch = 12 * nm / 7, centre = -6 * nm + 3.5 * pitch;
    node = mesh.node_sets.at("upper_zmin").front();
    mesh.coordinates[3 * node] = centre;
    mesh.coordinates[3 * node + 1] = centre;
    mesh.coordinates[3 * node + 2] = -depth;
  }
  // The slave node's normal force with the run's masses `mass` and step `dt`, and (when `unscaled_mass`
  // is given) the penalty reference of a mass-scaled run.
  double force(double mass, double dt, double unscaled_mass = 0.0, double unscaled_dt = 0.0) const {
    const auto n = static_cast<std::size_t>(mesh.node_count());
    ContactManager manager = test::one_interaction(mesh, "upper_zmin", "lower_zmax", InteractionSettings{},
                                                   std::vector<double>(n, mass), dt);
    if (unscaled_mass > 0.0) manager.set_unscaled_penalty_reference(std::vector<double>(n, unscaled_mass), unscaled_dt);
    std::vector<double> f(3 * n, 0.0);
    const std::vector<double> v(f.size(), 0.0);
    manager.compute_forces(mesh.coordinates.data(), v.data(), f.data());
    return f[3 * node + 2];
  }
};

TEST(ScaledPenalty, KeepsTheUnscaledStiffnessWhereTheNodesAreScaledWithTheStep) {
  const Penetration p;
  const double m0 = 1e-24, dt0 = 1e-15, F = 1.3;
  const double unscaled = p.force(m0, dt0);
  EXPECT_NEAR(unscaled, 0.8 * m0 / (dt0 * dt0) * p.depth, 1e-9 * unscaled);
  // Masses scaled by F^2 with the step: the same stiffness, with or without the reference.
  EXPECT_NEAR(p.force(F * F * m0, F * dt0, m0, dt0), unscaled, 1e-12 * unscaled);
  EXPECT_NEAR(p.force(F * F * m0, F * dt0), unscaled, 1e-12 * unscaled);
}

TEST(ScaledPenalty, NeverExceedsTheUnscaledRatioWhereTheNodesAreNotScaled) {
  const Penetration p;
  const double m0 = 1e-24, dt0 = 1e-15, F = 1.3;
  const double unscaled = p.force(m0, dt0);
  // The step grew, the masses did not: the unscaled stiffness would be k dt^2 / m_eff = F^2 s; the bound
  // holds it at s, F^2 softer (why the solver gives the surface nodes F^2 their mass: solver/setup/mass_scaling.hpp).
  EXPECT_NEAR(p.force(m0, F * dt0, m0, dt0), unscaled / (F * F), 1e-12 * unscaled);
  EXPECT_NEAR(p.force(m0, F * dt0), unscaled / (F * F), 1e-12 * unscaled);
}

TEST(ScaledPenalty, HeavierNodesThanTheStepNeedsKeepTheUnscaledStiffness) {
  const Penetration p;
  const double m0 = 1e-24, dt0 = 1e-15, F = 2.0;
  const double unscaled = p.force(m0, dt0);
  // Masses raised by more than F^2 (elements scaled past the target): the unscaled stiffness, not a stiffer one.
  EXPECT_NEAR(p.force(3.0 * F * F * m0, F * dt0, m0, dt0), unscaled, 1e-12 * unscaled);
  EXPECT_NEAR(p.force(3.0 * F * F * m0, F * dt0), 3.0 * unscaled, 1e-12 * unscaled);
}

}  // namespace
}  // namespace tribex::contact
