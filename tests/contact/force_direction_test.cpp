// SPDX-License-Identifier: MIT
// `force direction = axis` (InteractionSettings::force_along_axis): the node-to-face penalty force along the
// contact axis instead of the master face's normal, the small-slope contact of the half-space theories
// (contact/README.md "Force direction"). One slave node 0.05 nm (vertically) below the centre of a master
// face tilted by slope t = 0.15 in x: the normal gap is 0.05 nm / sqrt(1 + t^2); the default force lies
// along the face normal (-t, 0, 1)/sqrt(1 + t^2); with the axis (0, 0, 1) the same magnitude points along z.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support.hpp"

namespace tribex::contact {
namespace {

using test::nm;

constexpr double kSlope = 0.15;

struct TiltedFace {
  mesh::Mesh mesh = test::two_flats({.gap = 1 * nm});
  int node = -1;
  std::vector<int> master;
  TiltedFace() {
    master = mesh.node_sets.at("lower_zmax");
    // Tilt the master box (z in [-2, 0] nm; the slave box starts at z = 1 nm): z += t x.
    for (int k = 0; k < mesh.node_count(); ++k)
      if (mesh.coordinates[3 * k + 2] < 0.5 * nm) mesh.coordinates[3 * k + 2] += kSlope * mesh.coordinates[3 * k];
    const double pitch = 12 * nm / 7, centre = -6 * nm + 3.5 * pitch;
    node = mesh.node_sets.at("upper_zmin").front();
    mesh.coordinates[3 * node] = centre;
    mesh.coordinates[3 * node + 1] = centre;
    mesh.coordinates[3 * node + 2] = kSlope * centre - 0.05 * nm;
  }
  // Contact forces [node][3] with the penalty force along the master normal or along the axis (0, 0, 1).
  std::vector<double> forces(bool along_axis) const {
    const auto n = static_cast<std::size_t>(mesh.node_count());
    InteractionSettings s;
    s.force_along_axis = along_axis;
    ContactManager manager = test::one_interaction(mesh, "upper_zmin", "lower_zmax", s, std::vector<double>(n, 1e-24));
    const double point[3] = {0.0, 0.0, 0.0}, direction[3] = {0.0, 0.0, 2.0};  // not unit: set_axis normalises
    manager.set_axis(point, direction);
    std::vector<double> f(3 * n, 0.0);
    const std::vector<double> v(f.size(), 0.0);
    manager.compute_forces(mesh.coordinates.data(), v.data(), f.data());
    return f;
  }
};

TEST(ForceDirection, NormalByDefaultAlongTheAxisWhenAsked) {
  const TiltedFace t;
  const double norm = std::sqrt(1.0 + kSlope * kSlope);
  const auto normal = t.forces(false);
  const double* fn = &normal[3 * t.node];
  const double magnitude = std::sqrt(fn[0] * fn[0] + fn[1] * fn[1] + fn[2] * fn[2]);
  ASSERT_GT(magnitude, 0.0);
  // Default: along the tilted face's outward normal (-t, 0, 1)/sqrt(1 + t^2).
  EXPECT_NEAR(fn[0] / magnitude, -kSlope / norm, 1e-9);
  EXPECT_NEAR(fn[1] / magnitude, 0.0, 1e-9);
  EXPECT_NEAR(fn[2] / magnitude, 1.0 / norm, 1e-9);
  // The magnitude is k_p g with g the normal gap: m_eff = 0.8 m (scaled_penalty_test.cpp), s = 1, dt = 1e-15 s.
  // 1e-4: the normal projection lands g t/sqrt(1 + t^2) = 0.007 nm off the face centre, so N_a differ from 1/4
  // by 0.4 % and m_eff (quadratic in them about the centre) by about 1.5e-5.
  EXPECT_NEAR(magnitude, 0.8 * 1e-24 / 1e-30 * 0.05 * nm / norm, 1e-4 * magnitude);
  const auto axis = t.forces(true);
  const double* fa = &axis[3 * t.node];
  EXPECT_NEAR(fa[0], 0.0, 1e-12 * magnitude);
  EXPECT_NEAR(fa[1], 0.0, 1e-12 * magnitude);
  EXPECT_NEAR(fa[2], magnitude, 1e-12 * magnitude);
  // Momentum: the master face's nodes take the opposite force, component by component.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(test::force_sum(axis, t.master, i), -fa[i], 1e-9 * magnitude);
}

}  // namespace
}  // namespace tribex::contact
