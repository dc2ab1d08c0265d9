// SPDX-License-Identifier: MIT
// A slave node below a fold of the master (issue 22): the master's top face folded into a valley
// along one grid line, as a soft master folds under a stiff slave's point loads, and a slave node
// 0.05 nm below the valley's bottom edge. No master face projects that node in its interior (it
// lies behind both faces that meet at the fold), so before the fix it got no force. Now its closest
// point is the edge point above it: gap = -0.05 nm, normal +z, and the penalty force k_p |g| with
// k_p = s m_eff / dt^2, m_eff = m_s m_M / (m_s + m_M), 1/m_M = sum_a N_a^2 / m_a = 2 (1/2)^2 / m.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support.hpp"

namespace tribex::contact {
namespace {

using test::nm;

TEST(ContactKink, SlaveNodeBelowAFoldOfTheMasterIsPushedOutAlongTheDistance) {
  mesh::Mesh m = test::two_flats({.gap = 1 * nm});
  const double pitch = 12 * nm / 7, x_fold = -6 * nm + 3 * pitch, y_mid = -6 * nm + 3.5 * pitch;
  const double depth = 0.3 * nm, below = 0.05 * nm;
  // Fold the master's top face: the nodes of one grid line go down by `depth`.
  for (int n : m.node_sets.at("lower_zmax")) {
    double* X = &m.coordinates[3 * n];
    if (std::abs(X[0] - x_fold) < 1e-3 * nm) X[2] -= depth;
  }
  // One slave node goes below the middle of the fold's bottom edge.
  const int node = m.node_sets.at("upper_zmin").front();
  m.coordinates[3 * node] = x_fold;
  m.coordinates[3 * node + 1] = y_mid;
  m.coordinates[3 * node + 2] = -depth - below;

  const double mass = 1e-24, dt = 1e-15;
  const std::vector<double> masses(static_cast<std::size_t>(m.node_count()), mass);
  InteractionSettings s;  // frictionless, penalty scale 1
  ContactManager manager = test::one_interaction(m, "upper_zmin", "lower_zmax", s, masses, dt);
  std::vector<double> force(3 * static_cast<std::size_t>(m.node_count()), 0.0);
  const std::vector<double> v(force.size(), 0.0);
  const ContactTotals totals = manager.compute_forces(m.coordinates.data(), v.data(), force.data());

  const double m_master = mass / 0.5, m_eff = mass * m_master / (mass + m_master);
  const double expected = m_eff / (dt * dt) * below;
  EXPECT_NEAR(force[3 * node + 2], expected, 1e-9 * expected);
  EXPECT_NEAR(force[3 * node + 0], 0.0, 1e-9 * expected);
  EXPECT_NEAR(force[3 * node + 1], 0.0, 1e-9 * expected);
  EXPECT_NEAR(totals.max_penetration, below, 1e-9 * below);
  EXPECT_EQ(totals.nodes, 1);
  // Action and reaction: the two master nodes of the edge carry -f between them.
  EXPECT_NEAR(test::force_sum(force, m.node_sets.at("lower_zmax"), 2), -expected, 1e-9 * expected);
}

}  // namespace
}  // namespace tribex::contact
