// SPDX-License-Identifier: MIT
// The backward-Euler junction shear (contact/models/junction_shear.hpp, docs/theory.md 7.3): stability
// where the explicit tanh damper fails, the caps (tau* A_I and the stick force), the sign and the
// bookkeeping of the dissipation, reversal; and in the manager, no overshoot when many slave nodes
// share master nodes (non-matching flats).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_manager.hpp"
#include "contact/models/junction_shear.hpp"
#include "support.hpp"

namespace tribex::contact {
namespace {

// A slave node of a 0.4 nm silicon surface mesh against a rigid flat: the sphere-sliding numbers.
constexpr double tau_star = 195e6;         // Pa
constexpr double area = 0.4e-9 * 0.4e-9;   // A_I, m^2
constexpr double capacity = tau_star * area;
constexpr double mass = 0.5 * 2330 * 0.4e-9 * 0.4e-9 * 0.4e-9;  // surface node, kg
constexpr double dt = 4e-14;               // s, about 0.9 h / c_d
constexpr double K = capacity * dt / mass;  // speed the full force removes in one step, m/s

JunctionLaw law(double v_ref) { return {tau_star, v_ref, 0.0}; }

// One free node on a rigid flat, only the shear acting: v^{n+3/2} = v^{n+1/2} + dt F / m.
double step_implicit(double v, double v_ref, double* power = nullptr) {
  const double vt[3] = {v, 0.0, 0.0};
  const JunctionUpdate up = junction_update(vt, vt, capacity, mass, dt, law(v_ref));
  if (power) *power = up.power;
  return v + dt * up.force[0] / mass;
}
double step_explicit(double v, double v_ref) {
  const double vt[3] = {v, 0.0, 0.0};
  double tau[3];
  junction_traction(vt, law(v_ref), tau);
  return v + dt * tau[0] * area / mass;
}

TEST(JunctionUpdate, SlipSpeedSolvesTheBackwardEulerEquation) {
  for (double v_ref : {1e-4, 0.1, 3.0, 100.0})
    for (double vp : {1e-6, 0.01, 1.0, 0.99 * K, K, 1.01 * K, 10.0 * K}) {
      const double s = junction_slip_speed(vp, K, v_ref);
      EXPECT_GE(s, 0.0);
      EXPECT_LE(s, vp);
      EXPECT_NEAR(s + K * std::tanh(s / v_ref), vp, 1e-12 * (vp + K)) << v_ref << " " << vp;
    }
  EXPECT_EQ(junction_slip_speed(0.0, K, 0.1), 0.0);
}

// docs/theory.md 7.3: the explicit damper c = tau* A_I / v_ref needs c dt / m = K / v_ref < 2.
TEST(JunctionUpdate, StableWhereTheExplicitDamperIsNot) {
  std::printf("K = tau* A_I dt / m = %.3g m/s\n", K);
  // Linear regime (|v| << v_ref): explicit amplification |1 - K/v_ref|, > 1 beyond the bound.
  const double v_ref_unstable = K / 2.5, v_ref_stable = K / 1.5;
  double ve = 1e-3 * v_ref_unstable, vs = 1e-3 * v_ref_stable;
  for (int n = 0; n < 10; ++n) {
    ve = step_explicit(ve, v_ref_unstable);
    vs = step_explicit(vs, v_ref_stable);
  }
  EXPECT_GT(std::abs(ve), 1e-3 * v_ref_unstable * std::pow(1.4, 10));  // grew by 1.5 per step
  EXPECT_LT(std::abs(vs), 1e-3 * v_ref_stable * std::pow(0.6, 10));    // decayed by 0.5 per step
  // A physically small v_ref (K / v_ref = 1e3 and more): explicit chatter of amplitude ~K that never
  // decays; backward Euler: |v| never grows, never changes sign, and the node sticks.
  for (double v_ref : {K / 2.5, 0.1, 1e-3}) {
    double v_exp = 1.0, v_imp = 1.0;
    bool sign_change = false, grew = false;
    for (int n = 0; n < 200; ++n) {
      v_exp = step_explicit(v_exp, v_ref);
      const double next = step_implicit(v_imp, v_ref);
      sign_change |= next < 0.0;
      grew |= next > v_imp;
      v_imp = next;
    }
    EXPECT_FALSE(sign_change) << v_ref;
    EXPECT_FALSE(grew) << v_ref;
    EXPECT_LT(v_imp, 1e-6) << v_ref;
    if (v_ref < K / 2) {
      EXPECT_GT(std::abs(v_exp), 0.1 * v_ref) << v_ref;  // the explicit update still chatters
    }
  }
}

TEST(JunctionUpdate, ForceCappedAtStrengthTimesAreaAndAtTheStickForce) {
  for (double v_ref : {1e-6, 0.1, 10.0})
    for (double vp : {1e-3, 0.5 * K, K, 2.0 * K, 50.0 * K}) {
      const double v[3] = {0.6 * vp, -0.8 * vp, 0.0};
      const JunctionUpdate up = junction_update(v, v, capacity, mass, dt, law(v_ref));
      const double f = std::hypot(up.force[0], up.force[1]);
      EXPECT_LE(f, capacity * (1 + 1e-12));
      EXPECT_LE(f, mass * vp / dt * (1 + 1e-12));
      // F = tau* A_I tanh(|v+| / v_ref) with |v+| = slip_speed: the law at the end of the step.
      EXPECT_NEAR(f, capacity * std::tanh(up.slip_speed / v_ref), 1e-9 * capacity);
    }
  // v_ref -> 0 is the kinematic cap of docs/theory.md 7.3: stick below K (force = -m v_pred / dt, the
  // pair stops), slip at the full capacity above it.
  const double slow[3] = {0.3 * K, 0.0, 0.0}, fast[3] = {3.0 * K, 0.0, 0.0};
  const JunctionUpdate stick = junction_update(slow, slow, capacity, mass, dt, law(1e-9));
  EXPECT_NEAR(stick.force[0], -mass * 0.3 * K / dt, 1e-6 * capacity);
  EXPECT_LT(stick.slip_speed, 1e-8);
  const JunctionUpdate slip = junction_update(fast, fast, capacity, mass, dt, law(1e-9));
  EXPECT_NEAR(slip.force[0], -capacity, 1e-12 * capacity);
  EXPECT_NEAR(slip.slip_speed, 2.0 * K, 1e-9 * K);
}

TEST(JunctionUpdate, ForceOpposesThePredictedSlipAndReversesWithIt) {
  for (double vp : {0.05, 1.0, 7.5, 100.0}) {
    const double fwd[3] = {vp, 0.0, 0.0}, back[3] = {-vp, 0.0, 0.0}, side[3] = {0.0, vp, 0.0};
    const JunctionUpdate a = junction_update(fwd, fwd, capacity, mass, dt, law(0.1));
    const JunctionUpdate b = junction_update(back, back, capacity, mass, dt, law(0.1));
    const JunctionUpdate c = junction_update(side, side, capacity, mass, dt, law(0.1));
    EXPECT_LT(a.force[0], 0.0);
    EXPECT_EQ(b.force[0], -a.force[0]);
    EXPECT_EQ(c.force[1], a.force[0]);
    EXPECT_EQ(c.force[0], 0.0);
    EXPECT_GT(a.power, 0.0);
    EXPECT_EQ(a.power, b.power);
  }
}

// A node sliding freely on a rigid flat at 500 m/s (about 30 steps of slip) decelerates under tau* A_I and stops: the
// dissipated energy sum(power dt) equals the kinetic energy lost (the ledger's pairing), every
// step dissipates (power >= 0), and the stopping distance is the Coulomb-like v0^2 m / (2 tau* A_I)
// to within one step's travel (v_ref small against v0).
TEST(JunctionUpdate, DissipationIsPositiveAndEqualsTheKineticEnergyLost) {
  const double v0 = 500.0, v_ref = 0.01;
  double v = v0, x = 0.0, dissipated = 0.0;
  for (int n = 0; n < 1000; ++n) {
    double power = 0.0;
    const double next = step_implicit(v, v_ref, &power);
    EXPECT_GE(power, 0.0) << n;
    dissipated += power * dt;
    v = next;
    x += dt * v;
  }
  const double ke0 = 0.5 * mass * v0 * v0, ke = 0.5 * mass * v * v;
  EXPECT_NEAR(dissipated, ke0 - ke, 1e-12 * ke0);
  EXPECT_LT(v, 1e-9);
  const double distance = v0 * v0 * mass / (2 * capacity);
  std::printf("stopping distance %.5g m, Coulomb-like %.5g m (one step of travel %.3g m)\n", x, distance, v0 * dt);
  EXPECT_NEAR(x, distance, v0 * dt);
}

// Many slave nodes on few master nodes (20 x 20 slave faces on 7 x 7 master faces, light master
// nodes): the pair masses count every pair that shares a master node (row sums), so iterating the
// velocity update with the shear alone is a Jacobi iteration whose operator has spectral radius
// below 1: the largest slip and the kinetic energy never grow, momentum is conserved, and the
// slip decays. (Single nodes can overshoot transiently: row-sum scaling bounds the spectrum, not
// each component.)
TEST(JunctionManagerCoupling, SharedMasterNodesStayStable) {
  const double nm = test::nm, z0 = 0.2e-9;
  const mesh::Mesh m = test::two_flats({});  // 20 x 20 slave faces at gap 0 on 7 x 7 master faces
  std::vector<double> node_mass(m.node_count(), 1e-24);
  const auto& master_nodes = m.node_sets.at("lower_zmax");
  for (int node : master_nodes) node_mass[node] = 2e-25;  // light master: strong coupling
  // stick: tau* A_I dt / m_pair >> the slip
  InteractionSettings s = test::junction_settings({0.05, z0, 5 * z0}, {1e9, 1e-6, 0.05 * z0});
  const double step = 1e-15;
  ContactManager manager = test::one_interaction(m, "upper_zmin", "lower_zmax", s, node_mass, step);
  std::vector<double> v(m.coordinates.size(), 0.0), force(m.coordinates.size(), 0.0);
  const auto& slave_nodes = m.node_sets.at("upper_zmin");
  for (int node : slave_nodes) v[3 * node] = 1.0;  // the slave face slides in +x at 1 m/s
  // x velocity of the master surface below a slave node (bilinear on the 7 x 7 grid).
  const double h = 12 * nm / 7;
  auto master_velocity = [&](double x, double y) {
    const int i = std::min(6, static_cast<int>((x + 6 * nm) / h)), j = std::min(6, static_cast<int>((y + 6 * nm) / h));
    const double xi = (x + 6 * nm - i * h) / h, eta = (y + 6 * nm - j * h) / h;
    double vm = 0.0;
    for (int n : master_nodes) {
      const int a = static_cast<int>(std::lround((m.coordinates[3 * n] + 6 * nm) / h)) - i;
      const int b = static_cast<int>(std::lround((m.coordinates[3 * n + 1] + 6 * nm) / h)) - j;
      if (a < 0 || a > 1 || b < 0 || b > 1) continue;
      vm += (a ? xi : 1 - xi) * (b ? eta : 1 - eta) * v[3 * n];
    }
    return vm;
  };
  auto x_momentum = [&] {
    double p = 0.0;
    for (int node : manager.surface_nodes()) p += node_mass[node] * v[3 * node];
    return p;
  };
  auto relative_kinetic_energy = [&] {  // x motion in the centre-of-momentum frame of the surface nodes
    double M = 0.0;
    for (int node : manager.surface_nodes()) M += node_mass[node];
    const double vc = x_momentum() / M;
    double e = 0.0;
    for (int node : manager.surface_nodes()) e += 0.5 * node_mass[node] * (v[3 * node] - vc) * (v[3 * node] - vc);
    return e;
  };
  const double p0 = x_momentum();
  double previous_worst = 1.0, previous_energy = relative_kinetic_energy(), worst = 1.0;
  for (int it = 0; it < 40; ++it) {
    std::fill(force.begin(), force.end(), 0.0);
    manager.compute_forces(m.coordinates.data(), v.data(), force.data(), nullptr, step);
    for (int node : manager.surface_nodes()) v[3 * node] += step * force[3 * node] / node_mass[node];
    worst = 0.0;
    for (int node : slave_nodes)
      worst = std::max(worst, std::abs(v[3 * node] - master_velocity(m.coordinates[3 * node], m.coordinates[3 * node + 1])));
    const double energy = relative_kinetic_energy();
    EXPECT_LE(worst, previous_worst * (1 + 1e-12)) << "iteration " << it;
    EXPECT_LE(energy, previous_energy * (1 + 1e-12)) << "iteration " << it;
    EXPECT_NEAR(x_momentum(), p0, 1e-12 * p0);
    previous_worst = worst;
    previous_energy = energy;
  }
  std::printf("largest |slip| after 40 shear-only updates: %.4g m/s (from 1)\n", worst);
  EXPECT_LT(worst, 0.1);
}

// The junction's contact area is the in-contact part of the slave faces, not a count of whole
// nodal areas: a slave slab tilted about y (gap g = slope (x - x_c)) on a flat is in contact for
// x <= x_c, so the area is (x_c + 5 nm) x 10 nm for any x_c, and the shear on it (sliding in y,
// heavy nodes) is tau* times that area. Whole nodal areas would move in steps of 0.5 nm x 10 nm.
TEST(JunctionManagerArea, ContactAreaFollowsTheGapBetweenNodes) {
  const double nm = test::nm, z0 = 0.2e-9, slope = 0.02, tau = 100e6, V = 10.0;
  for (double xc : {-2.1 * nm, -0.05 * nm, 0.2 * nm, 1.37 * nm, 3.5 * nm}) {
    mesh::Mesh m = test::two_flats({});  // 20 x 20 slave faces at gap 0 on 7 x 7 master faces, then tilted
    for (int node : m.node_sets.at("upper_all")) m.coordinates[3 * node + 2] += slope * (m.coordinates[3 * node] - xc);
    std::vector<double> node_mass(m.node_count(), 1e-20);
    InteractionSettings s = test::junction_settings({0.05, z0, 5 * z0}, {tau, 0.1, 0.0});  // in contact where g <= 0
    s.search_margin = 2 * nm;
    ContactManager manager = test::one_interaction(m, "upper_zmin", "lower_zmax", s, node_mass);
    std::vector<double> v(m.coordinates.size(), 0.0), force(m.coordinates.size(), 0.0);
    for (int node : m.node_sets.at("upper_all")) v[3 * node + 1] = V;
    const ContactTotals t = manager.compute_forces(m.coordinates.data(), v.data(), force.data());
    // The tilted face's true area is larger by sqrt(1 + slope^2) (the reference areas are used).
    const double expected = (xc + 5 * nm) * 10 * nm * std::sqrt(1 + slope * slope);
    std::printf("x_c = %+.2f nm: area %.5g nm^2, expected %.5g nm^2 (%+.3f %%)\n", xc / nm, t.area / (nm * nm),
                expected / (nm * nm), 100 * (t.area / expected - 1));
    // 8 x 8 samples per 0.5 nm face: the boundary is resolved to 1/16 of a face (half a sample).
    EXPECT_NEAR(t.area, expected, 0.5 * (0.5 * nm / 8) * 10 * nm) << xc / nm;
    EXPECT_NEAR(t.junction_capacity, tau * t.area, 1e-9 * tau * t.area);
    EXPECT_NEAR(t.tangential_force, tau * t.area, 1e-3 * tau * t.area);  // tanh(V / v_ref) = 1
  }
}

}  // namespace
}  // namespace tribex::contact
