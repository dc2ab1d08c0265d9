// SPDX-License-Identifier: MIT
// Coulomb friction on two flats (contact/laws/coulomb.hpp, docs/theory.md 7.5), one force evaluation
// per case against the closed forms. The slave slab penetrates the master by |g| = 1 pm, so every
// slave node carries the penalty force N_I; the master is prescribed (fixed) and 1000 times heavier,
// so a slave node's pair mass is its own mass m and the force that would hold it at a slip speed V is
// H = m V / dt. With dt = 1 fs and |g| = 1 pm, H / N_I = V x 1e-3 s/m x (m / m_eff) = 1.001 V x 1e-3 s/m:
// V = 100 m/s sticks (H < mu_k N), 450 m/s lies between mu_k N and mu_s N, 2000 m/s slides.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "tests/contact/support.hpp"

namespace tribex::contact {
namespace {

constexpr double nm = test::nm, mu_s = 0.5, mu_k = 0.4, dt = 1e-15, m = 1e-20;

struct Rig {
  mesh::Mesh mesh = test::two_flats({.gap = -1e-12});
  std::vector<double> mass, force;
  std::unique_ptr<ContactManager> manager;
  explicit Rig(double reference_speed = 0.0) : mass(static_cast<std::size_t>(mesh.node_count()), m) {
    for (int node : mesh.node_sets.at("lower_all")) mass[node] = 1000 * m;
    Coulomb law;
    law.static_coefficient = mu_s;
    law.kinetic_coefficient = mu_k;
    law.speed.reference_speed = reference_speed;
    InteractionSettings s;
    s.law = law;
    s.search_margin = 1 * nm;
    manager = std::make_unique<ContactManager>(test::one_interaction(mesh, "upper_zmin", "lower_zmax", s, mass, dt));
    std::vector<char> fixed(static_cast<std::size_t>(mesh.node_count()), 0);
    for (int node : mesh.node_sets.at("lower_all")) fixed[node] = 1;
    manager->set_prescribed_nodes(fixed);
  }
  // The slave slab slides along +x at V; returns the totals and leaves the forces in `force`.
  ContactTotals slide(double V) {
    std::vector<double> v(mesh.coordinates.size(), 0.0);
    for (int node : mesh.node_sets.at("upper_all")) v[3 * node] = V;
    force.assign(mesh.coordinates.size(), 0.0);
    return manager->compute_forces(mesh.coordinates.data(), v.data(), force.data(), nullptr, dt);
  }
  double friction_x() const { return test::force_sum(force, mesh.node_sets.at("upper_zmin"), 0); }
};

int slave_nodes(const Rig& r) { return static_cast<int>(r.mesh.node_sets.at("upper_zmin").size()); }

TEST(Coulomb, SticksBelowTheStaticLimit) {
  Rig r;
  const ContactTotals t = r.slide(100.0);
  const double hold = slave_nodes(r) * m * 100.0 / dt;  // every node held: relative velocity zero after the step
  EXPECT_NEAR(r.friction_x(), -hold, 1e-12 * hold);
  EXPECT_LT(hold, mu_k * t.compressive_force);
  EXPECT_NEAR(t.tangential_force, hold, 1e-12 * hold);
  EXPECT_NEAR(test::force_sum(r.force, r.mesh.node_sets.at("lower_zmax"), 0), hold, 1e-12 * hold);  // reaction
}

TEST(Coulomb, SlidesWithTheKineticForce) {
  Rig r;
  const ContactTotals t = r.slide(2000.0);
  EXPECT_NEAR(r.friction_x(), -mu_k * t.compressive_force, 1e-12 * t.compressive_force);
  EXPECT_NEAR(t.tangential_force, mu_k * t.normal_force, 1e-12 * t.normal_force);
  // Dissipation: the force against the mean of the slip speeds before and after the step.
  const double slip_after = 2000.0 - mu_k * t.compressive_force / slave_nodes(r) * dt / m;  // per node, uniform N here
  EXPECT_NEAR(t.friction_power, mu_k * t.compressive_force * 0.5 * (2000.0 + slip_after), 1e-6 * t.friction_power);
}

TEST(Coulomb, StaticAndKineticLimitsMakeAHysteresis) {
  // Between mu_k N and mu_s N a sliding node keeps sliding, a stuck one stays stuck.
  Rig sliding, stuck;
  sliding.slide(2000.0);
  const ContactTotals a = sliding.slide(450.0);
  EXPECT_NEAR(sliding.friction_x(), -mu_k * a.compressive_force, 1e-12 * a.compressive_force);
  const ContactTotals b = stuck.slide(450.0);
  const double hold = slave_nodes(stuck) * m * 450.0 / dt;
  EXPECT_NEAR(stuck.friction_x(), -hold, 1e-12 * hold);
  EXPECT_GT(hold, mu_k * b.compressive_force);
  EXPECT_LT(hold, mu_s * b.compressive_force);
  // The sliding node sticks again once the kinetic force would stop it within the step.
  const ContactTotals c = sliding.slide(100.0);
  EXPECT_NEAR(sliding.friction_x(), -slave_nodes(sliding) * m * 100.0 / dt, 1e-12 * c.compressive_force);
}

TEST(Coulomb, RegularisedStickCreepsAtTheTanhSpeed) {
  // v_ref > 0: the force is mu_s N tanh(s / v_ref) at the slip s after the step, the root of
  // s + K tanh(s / v_ref) = V with K = mu_s N_I dt / m (docs/theory.md 7.3): about 2 m/s of creep here,
  // where the exact stick (v_ref = 0) holds the node.
  const double v_ref = 10.0, V = 100.0;
  Rig r(v_ref);
  const ContactTotals t = r.slide(V);
  const double K = mu_s * t.compressive_force / slave_nodes(r) * dt / m;
  double lo = 0.0, hi = V;  // bisection on the increasing left side
  for (int i = 0; i < 200; ++i) {
    const double s = 0.5 * (lo + hi);
    (s + K * std::tanh(s / v_ref) < V ? lo : hi) = s;
  }
  const double creep = 0.5 * (lo + hi);
  EXPECT_GT(creep, 1.0);
  EXPECT_NEAR(-r.friction_x(), slave_nodes(r) * m * (V - creep) / dt, 1e-4 * slave_nodes(r) * m * V / dt);
}

}  // namespace
}  // namespace tribex::contact
