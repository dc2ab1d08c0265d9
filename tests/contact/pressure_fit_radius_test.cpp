// SPDX-License-Identifier: MIT
// contact_radius_pressure_fit (ContactManager::pressure_fit_radius): a flat slave grid pressed into a
// flat master with the penetration of an elliptic (Hertz) pressure, g(r) = -g0 sqrt(1 - r^2/a^2).
// The slave nodes sit over master face centres, so every node has the same penalty stiffness and
// its nodal pressure f/A is exactly proportional to its penetration: the fit must return a to
// round-off for any a between node rings, where the node-ring measures step.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_manager.hpp"
#include "support.hpp"

namespace tribex::contact {
namespace {

using test::nm;

// Master slab 12 x 12 nm (0.5 nm faces, top at z = 0); slave slab 10 x 10 nm (0.5 nm faces)
// shifted by half a face, so its nodes lie over master face centres; slave nodes within a of the
// axis pushed to g(r) = -g0 sqrt(1 - r^2/a^2), the others 0.05 nm above the master.
ContactTotals press(double a, double g0) {
  const mesh::Mesh m = test::two_flats({.master_intervals = {24, 24}, .slave_origin = {-5.25 * nm, -5.25 * nm}});
  const std::vector<double> mass(m.node_count(), 1e-24);
  ContactManager manager = test::one_interaction(m, "upper_zmin", "lower_zmax", InteractionSettings{}, mass);
  std::vector<double> x = m.coordinates;
  for (int node : manager.surfaces()[0].nodes) {
    const double r2 = x[3 * node] * x[3 * node] + x[3 * node + 1] * x[3 * node + 1];
    x[3 * node + 2] = r2 < a * a ? -g0 * std::sqrt(1.0 - r2 / (a * a)) : 0.05 * nm;
  }
  const double point[3] = {0, 0, 0}, axis[3] = {0, 0, 1};
  manager.set_axis(point, axis);
  std::vector<double> force(m.coordinates.size(), 0.0);
  const std::vector<double> v(m.coordinates.size(), 0.0);
  return manager.compute_forces(x.data(), v.data(), force.data());
}

TEST(PressureFitRadius, RecoversTheRadiusOfAnEllipticPressureBetweenNodeRings) {
  // Radii at, between and just past node rings of the 0.5 nm grid (nodes at +-0.25, +-0.75, ... nm).
  for (double a : {1.3 * nm, 2.1 * nm, 2.6 * nm, 3.33 * nm, 4.05 * nm}) {
    const ContactTotals t = press(a, 0.01 * nm);
    ASSERT_GT(t.nodes, 3) << a;
    EXPECT_NEAR(t.radius_pressure_fit, a, 1e-9 * a) << "a = " << a / nm << " nm";
    // The node-ring measure differs from a by up to a node spacing: the fit is what removes that.
    EXPECT_GT(std::abs(std::sqrt(t.area / M_PI) - a), 1e-4 * nm) << a;
  }
}

TEST(PressureFitRadius, IsZeroWithoutEnoughContactNodes) {
  // a = 0.4 nm: only the four nodes at (+-0.25, +-0.25) nm are inside, all at the same radius
  // (no spread in r^2 to fit): 0, not a number from a degenerate fit.
  const ContactTotals t = press(0.4 * nm, 0.01 * nm);
  EXPECT_EQ(t.nodes, 4);
  EXPECT_EQ(t.radius_pressure_fit, 0.0);
  const ContactTotals none = press(0.1 * nm, 0.01 * nm);
  EXPECT_EQ(none.nodes, 0);
  EXPECT_EQ(none.radius_pressure_fit, 0.0);
}

}  // namespace
}  // namespace tribex::contact
