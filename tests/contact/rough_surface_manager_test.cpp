// SPDX-License-Identifier: MIT
// The rough-surface model in the contact manager: flats at a fixed gap carry the GW law times the
// nominal area (apparent pressure, real area, asperity count and junction friction against the GW
// integrals evaluated directly), and the stable-step bound of the contact springs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/contact_manager.hpp"
#include "contact/rough/gw_integrals.hpp"
#include "support.hpp"

namespace tribex::contact {
namespace {

using test::nm;

// Summits of a 1 um^2 patch: eta = 50 /um^2, R = 200 nm, sigma_s = 2 nm; E* = 90 GPa, W = 0.05 J/m^2.
RoughSurfaceParameters patch() {
  RoughSurfaceParameters q;
  q.summit_density = 50e12;
  q.summit_radius = 200 * nm;
  q.sigma_s = 2 * nm;
  q.composite_modulus = 90e9;
  q.work_of_adhesion = 0.05;
  return q;
}

struct Result {
  ContactTotals totals;
  double force_z_slave = 0.0, force_z_master = 0.0, force_x_slave = 0.0;
  double stable_dt = 0.0;
};

Result run(double gap, double offset, double slide_speed, const RoughSurfaceParameters& q, double tau = 0.0) {
  // Master slab 12 x 12 nm (top at z = 0), slave slab 10 x 10 nm (bottom at z = gap), different grids.
  const mesh::Mesh m = test::two_flats({.gap = gap, .slave_intervals = {6, 5}});
  std::vector<double> mass(m.node_count(), 1e-21);
  InteractionSettings s;
  RoughSurface law;
  law.law = std::make_shared<const RoughSurfaceLaw>(q);
  law.mean_plane_offset = offset;
  law.shear.strength = tau;
  law.shear.reference_speed = 0.1;
  s.law = law;
  s.search_margin = 20 * nm;
  ContactManager manager = test::one_interaction(m, "upper_zmin", "lower_zmax", s, mass);
  std::vector<double> v(m.coordinates.size(), 0.0), force(m.coordinates.size(), 0.0);
  for (int node : m.node_sets.at("upper_all")) v[3 * node] = slide_speed;
  Result r;
  r.totals = manager.compute_forces(m.coordinates.data(), v.data(), force.data());
  r.force_z_slave = test::force_sum(force, m.node_sets.at("upper_zmin"), 2);
  r.force_x_slave = test::force_sum(force, m.node_sets.at("upper_zmin"), 0);
  r.force_z_master = test::force_sum(force, m.node_sets.at("lower_zmax"), 2);
  r.stable_dt = manager.stable_time_step();
  return r;
}

// Acceptance (issue 10): apparent pressure, real area and friction against the GW integrals evaluated
// directly, within 0.5 %, over separations from deep contact to the last asperities.
TEST(RoughSurfaceManager, FlatsCarryTheDirectGwIntegralsTimesTheNominalArea) {
  const auto q = patch();
  const double A0 = 100 * nm * nm, tau = 50e6, V = 1.0;
  const double hertz = q.summit_density * (4.0 / 3.0) * q.composite_modulus * std::sqrt(q.summit_radius) * std::pow(q.sigma_s, 1.5);
  double worst_p = 0.0, worst_a = 0.0, worst_f = 0.0;
  for (double t : {-1.013, -0.307, 0.011, 0.713, 1.517, 2.509, 3.503, 4.511}) {  // off the table nodes
    const double offset = 1.0 * nm;  // d = gap + 1 nm
    const double d = t * q.sigma_s, gap = d - offset;
    const Result r = run(gap, offset, V, q, tau);
    const double p = q.summit_density * (hertz / q.summit_density * gw::gw_integral(1.5, t) -
                                         2 * M_PI * q.work_of_adhesion * q.summit_radius * gw::gw_integral(0.0, t));
    const double ac = M_PI * q.summit_density * q.summit_radius * q.sigma_s * gw::gw_integral(1.0, t);
    const double friction = tau * ac * A0 * std::tanh(V / 0.1);
    const double err_p = std::abs(r.totals.apparent_pressure() - p) / std::abs(p);
    const double err_a = std::abs(r.totals.real_area / (ac * A0) - 1);
    const double err_f = std::abs(r.totals.tangential_force / friction - 1);
    std::printf("t = %5.2f: apparent pressure %.5g Pa (direct %.5g, %.1e), real area %.5g m^2 (%.1e), friction %.5g N (%.1e), "
                "asperities %.4g\n",
                t, r.totals.apparent_pressure(), p, err_p, r.totals.real_area, err_a, r.totals.tangential_force, err_f,
                r.totals.asperity_contacts);
    worst_p = std::max(worst_p, err_p);
    worst_a = std::max(worst_a, err_a);
    worst_f = std::max(worst_f, err_f);
    EXPECT_NEAR(r.totals.nominal_area, A0, 1e-9 * A0);
    const double pull = q.summit_density * 2 * M_PI * q.work_of_adhesion * q.summit_radius * gw::gw_integral(0.0, t) * A0;
    EXPECT_NEAR(r.totals.adhesive_force, pull, 1e-5 * pull);  // the DMT part (Eq. 4.10) alone
    EXPECT_NEAR(r.totals.compressive_force - r.totals.adhesive_force, r.totals.normal_force, 1e-12 * std::abs(r.totals.normal_force));
    EXPECT_NEAR(r.totals.asperity_contacts, q.summit_density * A0 * gw::gw_integral(0.0, t), 1e-5 * q.summit_density * A0);
    // Newton's third law and the sign: p > 0 pushes the slave up (+z) and the master down.
    EXPECT_NEAR(r.force_z_slave, p * A0, 0.005 * std::abs(p) * A0);
    EXPECT_NEAR(r.force_z_master, -r.force_z_slave, 1e-9 * std::abs(r.force_z_slave));
    EXPECT_NEAR(r.force_x_slave, -friction, 0.005 * friction);  // opposes the slide
  }
  EXPECT_LT(worst_p, 0.005);
  EXPECT_LT(worst_a, 0.005);
  EXPECT_LT(worst_f, 0.005);
}

TEST(RoughSurfaceManager, NothingBeyondTheContactSeparation) {
  const Result r = run(6.5 * 2 * nm, 0.0, 1.0, patch(), 50e6);
  EXPECT_EQ(r.totals.normal_force, 0.0);
  EXPECT_EQ(r.totals.real_area, 0.0);
  EXPECT_EQ(r.totals.tangential_force, 0.0);
  EXPECT_TRUE(std::isinf(r.stable_dt));
}

// The stable step of the springs k_I = A_I dp/dd: 2 sqrt(m_eff / k_I), m_eff = m_s m_M / (m_s + m_M) with
// 1/m_M = sum_a N_a^2 / m_a, so m/2 <= m_eff < m for equal masses m; the interior slave nodes carry the
// largest A_I (10 x 10 nm / (6 x 5) faces) and set the bound.
TEST(RoughSurfaceManager, StableStepFromThePressureSlope) {
  const auto q = patch();
  const double d = 0.5 * q.sigma_s, m = 1e-21;
  const Result r = run(d, 0.0, 0.0, q);
  const RoughSurfaceLaw law(q);
  const double k = law.evaluate(d).stiffness * (10.0 / 6.0) * (10.0 / 5.0) * nm * nm;
  std::printf("stable step %.5g s; bounds %.5g (m_eff = m/2) to %.5g s (m_eff = m)\n", r.stable_dt,
              2.0 * std::sqrt(0.5 * m / k), 2.0 * std::sqrt(m / k));
  EXPECT_GE(r.stable_dt, 2.0 * std::sqrt(0.5 * m / k) * (1 - 1e-12));
  EXPECT_LT(r.stable_dt, 2.0 * std::sqrt(m / k));
}

// Discrete population (few asperities): the manager's load and area equal the direct sum over the
// summits times A_0 / A_map.
TEST(RoughSurfaceManager, DiscretePopulationMatchesDirectSum) {
  RoughSurfaceParameters q;
  q.composite_modulus = 90e9;
  q.work_of_adhesion = 0.05;
  q.summit_heights = {3 * nm, 1 * nm, -1 * nm, 0.5 * nm, -3.5 * nm};  // mean 0
  q.summit_radii = {100 * nm, 150 * nm, 80 * nm, 300 * nm, 120 * nm};
  q.map_area = 1e-14;
  const double A0 = 100 * nm * nm;
  for (double d : {2.5 * nm, 0.7 * nm, -0.2 * nm, -2 * nm}) {
    const Result r = run(d, 0.0, 0.0, q);
    double load = 0.0, area = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < q.summit_heights.size(); ++i) {
      const double w = q.summit_heights[i] - d, R = q.summit_radii[i];
      if (w <= 0) continue;
      load += (4.0 / 3.0) * q.composite_modulus * std::sqrt(R) * std::pow(w, 1.5) - 2 * M_PI * q.work_of_adhesion * R;
      area += M_PI * R * w;
      ++count;
    }
    EXPECT_NEAR(r.totals.normal_force, load * A0 / q.map_area, 0.01 * std::abs(load) * A0 / q.map_area) << d;
    EXPECT_NEAR(r.totals.real_area, area * A0 / q.map_area, 0.01 * area * A0 / q.map_area) << d;
    EXPECT_NEAR(r.totals.asperity_contacts, count * A0 / q.map_area, 1e-9 * A0 / q.map_area) << d;
  }
}

}  // namespace
}  // namespace tribex::contact
