// SPDX-License-Identifier: MIT
// Selective mass scaling (solver/setup/mass_scaling.hpp, docs/theory.md 1.4.1): the density factor per element,
// the lumped masses, the blocks filter, the stable step it gives, the added-mass guard, the set-up
// errors, the kinetic-energy limit of the run guards, and mass damping with the unscaled masses.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "solver/errors.hpp"
#include "solver/guards/run_guards.hpp"
#include "solver/integrators/central_difference.hpp"
#include "solver/setup/mass_scaling.hpp"
#include "solver/model.hpp"
#include "solver/stable_time_step.hpp"
#include "tests/solver/support.hpp"

namespace tribex::solver {
namespace {

// Two separate unit cubes of steel: block "b" in 2 x 2 x 2 elements (edge 0.5 m), block "c" one element
// (edge 1 m), so c's stable step is twice b's. Time step scale factor 0.9 (the default).
inputs::Deck two_blocks(inputs::MassScalingSpec scaling) {
  inputs::Deck deck = test::box_deck(2, 1.0, "elastic", inputs::ElementFormulation::mean_quadrature);
  auto& fem = deck.models[0];
  inputs::GeneratedBoxSpec c = fem.boxes[0];
  c.block_name = "c";
  c.origin = {2.0, 0.0, 0.0};
  c.intervals = {1, 1, 1};
  fem.boxes.push_back(c);
  auto params = fem.blocks[0];
  params.block = "c";
  fem.blocks.push_back(params);
  deck.procedure.time_control.time_step_scale_factor = 0.9;
  deck.procedure.region.mass_scaling = scaling;
  return deck;
}

inputs::MassScalingSpec factor(double f, std::vector<std::string> blocks = {}) {
  inputs::MassScalingSpec s;
  s.largest_factor = f;
  s.blocks = std::move(blocks);
  return s;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(MassScaling, FactorIsTheSquaredStepRatioBelowTheTargetOnly) {
  EXPECT_DOUBLE_EQ(mass_scale_factor(0.5e-9, 1e-9), 4.0);   // half the target: 4x the mass
  EXPECT_DOUBLE_EQ(mass_scale_factor(0.8e-9, 1e-9), 1.5625);
  EXPECT_EQ(mass_scale_factor(1e-9, 1e-9), 1.0);            // at the target: untouched
  EXPECT_EQ(mass_scale_factor(3e-9, 1e-9), 1.0);            // above: untouched
}

TEST(MassScaling, ElementsAtHalfTheTargetGetFourTimesTheirMassOthersKeepIt) {
  inputs::Deck unscaled_deck = two_blocks(factor(2.0));
  unscaled_deck.procedure.region.mass_scaling.reset();
  const Model unscaled = build_model(unscaled_deck);
  const StableStep dt0 = compute_stable_time_step(unscaled, nullptr);

  const Model m = build_model(two_blocks(factor(2.0)));
  const MassScalingReport& r = m.mass_scaling;
  ASSERT_TRUE(r.active);
  ASSERT_EQ(r.blocks.size(), 2u);
  EXPECT_NEAR(r.unscaled_time_step, 0.9 * dt0.dt, 1e-15 * dt0.dt);
  EXPECT_NEAR(r.target_time_step, 2 * 0.9 * dt0.dt, 1e-15 * dt0.dt);
  // Block b (8 elements at the smallest step, half the target): density x 4, 3 x its 7800 kg added.
  EXPECT_EQ(r.blocks[0].scaled_elements, 8);
  for (double s : m.blocks[0].mass_scale) EXPECT_NEAR(s, 4.0, 1e-12);
  EXPECT_NEAR(r.blocks[0].mass, 7800.0, 1e-9);
  EXPECT_NEAR(r.blocks[0].added_mass, 3 * 7800.0, 1e-8);
  // Block c (edge 1 m: its step is twice b's, at the target): untouched to round-off.
  EXPECT_NEAR(r.blocks[1].added_mass, 0.0, 1e-9 * 7800.0);
  EXPECT_NEAR(r.added_fraction(), 3 * 7800.0 / 15600.0, 1e-12);
  // Lumped: the nodal masses hold the scaled element masses, 8 rho V0 s_e / 8 per element.
  EXPECT_NEAR(sum(m.mass), 4 * 7800.0 + 7800.0, 1e-8);
  EXPECT_NEAR(sum(unscaled.mass), 15600.0, 1e-8);
  EXPECT_DOUBLE_EQ(m.total_mass, unscaled.total_mass);  // total_mass stays the physical mass
  // The stable step on the scaled densities is the target (before the scale factor): the run's step.
  const StableStep dt1 = compute_stable_time_step(m, nullptr);
  EXPECT_NEAR(0.9 * dt1.dt, r.target_time_step, 1e-12 * r.target_time_step);
  // The same on a deformed configuration uses the scaled density too: block b stretched 5 % along x,
  // element by element the scaled estimate is sqrt(4) = 2 x the unscaled one in b, equal in c.
  std::vector<double> u(3 * static_cast<std::size_t>(m.mesh.node_count()), 0.0);
  for (int n = 0; n < m.mesh.node_count(); ++n)
    if (m.mesh.coordinates[3 * n] < 1.5) u[3 * n] = 0.05 * m.mesh.coordinates[3 * n];
  std::vector<double> dt_unscaled(m.mesh.element_count()), dt_scaled(m.mesh.element_count());
  compute_stable_time_step(unscaled, u.data(), dt_unscaled.data());
  compute_stable_time_step(m, u.data(), dt_scaled.data());
  for (int e = 0; e < m.mesh.element_count(); ++e) {
    const double ratio = m.element_block[e] == 0 ? 2.0 : 1.0;
    EXPECT_NEAR(dt_scaled[e], ratio * dt_unscaled[e], 1e-12 * dt_scaled[e]) << "element " << e;
  }
  EXPECT_GT(std::abs(dt_unscaled[0] - dt0.dt), 0.005 * dt0.dt);  // the stretch did change the estimate
  // The added-mass guard: 150 % is far above the default 5 %.
  EXPECT_TRUE(r.exceeds_limit());
  EXPECT_NE(r.limit_message().find("above 'maximum added mass fraction' 5 %"), std::string::npos) << r.limit_message();
}

// Contact between b's xmax face (9 nodes, scaled x 4 with their elements) and c's xmin face (4 nodes,
// c unscaled: its step is at the target). At twice the step the unscaled penalty s m_eff,0 / dt_0^2 would be
// k dt^2 / m_eff = 4 s on c's nodes, and c's elements would use twice the share of the step they used
// unscaled: the contact surface nodes get at least (dt / dt_0)^2 = 4 x their unscaled mass, so both meet
// the scaled step as unscaled (docs/theory.md 1.4.1): c's four face nodes 975 -> 3900 kg, b's face
// nodes (at 4 x already) as they were; the penalty scale factor does not change it.
TEST(MassScaling, ContactSurfaceNodesGetTheStepRatioSquaredTimesTheirUnscaledMass) {
  auto with_contact = [](inputs::Deck deck) {
    deck.procedure.region.contact = test::one_contact("c_face", "c_xmin", "b_face", "b_xmax");
    return deck;
  };
  const Model plain = build_model(two_blocks(factor(2.0)));
  const Model m = build_model(with_contact(two_blocks(factor(2.0))));
  inputs::Deck unscaled_deck = with_contact(two_blocks(factor(2.0)));
  unscaled_deck.procedure.region.mass_scaling.reset();
  const Model unscaled = build_model(unscaled_deck);
  const MassScalingReport& r = m.mass_scaling;
  ASSERT_TRUE(r.active);
  EXPECT_NEAR(r.contact_mass_factor, 4.0, 1e-12);
  EXPECT_EQ(r.contact_nodes, 4);
  EXPECT_NEAR(r.contact_added_mass, 4 * 3 * 975.0, 1e-8);
  EXPECT_NEAR(r.added_mass, 3 * 7800.0 + 4 * 3 * 975.0, 1e-8);
  const auto& c_face = m.mesh.node_sets.at("c_xmin");
  const auto& b_face = m.mesh.node_sets.at("b_xmax");
  ASSERT_EQ(c_face.size(), 4u);
  ASSERT_EQ(b_face.size(), 9u);
  for (int n : c_face) {
    EXPECT_NEAR(unscaled.mass[n], 975.0, 1e-9);
    EXPECT_NEAR(m.mass[n], 4.0 * unscaled.mass[n], 1e-9) << "node " << n;
  }
  for (int n : b_face) EXPECT_EQ(m.mass[n], plain.mass[n]) << "node " << n;  // scaled x 4 with b already
  EXPECT_NEAR(sum(m.mass), sum(plain.mass) + 4 * 3 * 975.0, 1e-8);
  bool found = false;
  for (const auto& line : r.lines()) found = found || line.find("contact surfaces: 4 nodes raised to 4 x") != std::string::npos;
  EXPECT_TRUE(found);
  // Penalty scale 0.5: the same raise (the elements' share of the step does not depend on it).
  // Without contact nothing is raised.
  inputs::Deck soft = with_contact(two_blocks(factor(2.0)));
  soft.procedure.region.contact->penalty_scale_factor = 0.5;
  const Model half = build_model(soft);
  EXPECT_NEAR(half.mass_scaling.contact_mass_factor, 4.0, 1e-12);
  for (int n : c_face) EXPECT_EQ(half.mass[n], m.mass[n]) << "node " << n;
  EXPECT_EQ(plain.mass_scaling.contact_nodes, 0);
  EXPECT_EQ(plain.mass_scaling.contact_added_mass, 0.0);
}

TEST(MassScaling, BlocksFilterScalesOnlyTheListedBlocks) {
  // Target 3 x the unscaled step, block c only: c (at 2/3 of the target) gets (3/2)^2, b keeps its
  // mass although it is below the target (it then still sets the step).
  const Model m = build_model(two_blocks(factor(3.0, {"c"})));
  const MassScalingReport& r = m.mass_scaling;
  EXPECT_FALSE(r.blocks[0].listed);
  EXPECT_TRUE(m.blocks[0].mass_scale.empty());
  EXPECT_EQ(r.blocks[0].added_mass, 0.0);
  EXPECT_TRUE(r.blocks[1].listed);
  EXPECT_EQ(r.blocks[1].scaled_elements, 1);
  ASSERT_EQ(m.blocks[1].mass_scale.size(), 1u);
  EXPECT_NEAR(m.blocks[1].mass_scale[0], 2.25, 1e-12);
  EXPECT_NEAR(r.added_mass, 1.25 * 7800.0, 1e-8);
  EXPECT_NEAR(r.added_fraction(), 1.25 * 7800.0 / 15600.0, 1e-12);
  EXPECT_NEAR(0.9 * compute_stable_time_step(m, nullptr).dt, r.unscaled_time_step, 1e-12 * r.unscaled_time_step);
}

TEST(MassScaling, AddedMassGuardHonoursTheDeckLimit) {
  inputs::MassScalingSpec s = factor(3.0, {"c"});
  s.maximum_added_mass_fraction = 0.7;  // 62.5 % added: below
  EXPECT_FALSE(build_model(two_blocks(s)).mass_scaling.exceeds_limit());
  s.maximum_added_mass_fraction = 0.6;
  EXPECT_TRUE(build_model(two_blocks(s)).mass_scaling.exceeds_limit());
}

TEST(MassScaling, SetUpErrorsNameTheKeyAndTheFix) {
  inputs::MassScalingSpec unknown = factor(2.0, {"cc"});
  unknown.blocks_where = {"deck.i", 40, 9};
  try {
    build_model(two_blocks(unknown));
    FAIL() << "an unknown block was accepted";
  } catch (const SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.i:40:9: error: 'blocks' of 'begin mass scaling' names block 'cc'"),
              std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("did you mean 'c'"), std::string::npos) << e.what();
  }
  inputs::MassScalingSpec low;
  low.target_time_step = 1e-9;  // far below the unscaled step of a 0.5 m steel element (~ 5e-5 s)
  low.target_where = {"deck.i", 41, 9};
  try {
    build_model(two_blocks(low));
    FAIL() << "a target below the unscaled step was accepted";
  } catch (const SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.i:41:9: error: 'target time step' 1e-09 s is not above the run's time "
                                         "step without mass scaling"),
              std::string::npos) << e.what();
  }
  inputs::Deck capped = two_blocks(factor(2.0));
  capped.procedure.time_control.maximum_time_step = 1e-6;
  EXPECT_THROW(build_model(capped), SetupError);  // the target is above 'maximum time step'
}

// Load to 0.5 J and unload over 1000 steps; kinetic energy 0.01 x internal while loaded, a start
// transient (kinetic 100 x internal for 20 steps, as at a first contact) and kinetic far above internal
// after the unload; from step 600, `ratio` x internal for `span` steps.
static std::pair<std::string, std::vector<RunWarning>> quasi_static_run(double ratio, long span, long* stopped_at = nullptr,
                                                                        std::string* stop_message = nullptr) {
  inputs::GuardSpec spec;
  spec.quasi_static = true;
  spec.kinetic_energy_limit = 0.1;
  RunGuards g(spec, SetupFindings{}, 1000, [](const RunWarning&) {});
  for (long n = 0; n < 1000; ++n) {
    Energies e;
    e.internal = n < 500 ? 1e-3 * n : 1e-3 * (1000 - n);
    e.kinetic = n < 20 ? 100 * e.internal : (n >= 600 && n < 600 + span) ? ratio * e.internal : n < 960 ? 0.01 * e.internal : 1.0;
    e.external_work = e.kinetic + e.internal;
    try {
      g.observe(n, 1e-12 * n, e, nullptr);
    } catch (const NumericalFailure& f) {
      if (stopped_at) *stopped_at = n;
      if (stop_message) *stop_message = f.what();
      return {g.finish(), g.warnings()};
    }
  }
  return {g.finish(), g.warnings()};
}

TEST(MassScaling, KineticEnergyLimitFailsALoadedQuasiStaticRunAtTheEnd) {
  // 30 % for 30 steps (3 % of the run, under the 5 % that stops it mid-run): judged at the end.
  long stopped = -1;
  const auto [fails, warned] = quasi_static_run(0.3, 30, &stopped);
  EXPECT_EQ(stopped, -1) << "a 30-step excess stopped the run";
  EXPECT_NE(fails.find("reached 30 % of internal energy at step 600"), std::string::npos) << fails;
  EXPECT_NE(fails.find("above 'maximum kinetic energy ratio' 10 %"), std::string::npos) << fails;
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_STREQ(kind_name(warned[0].kind), "kinetic_energy");
  const auto [passes, warned8] = quasi_static_run(0.08, 360, &stopped);  // 8 %: warned (above 5 %), within the limit
  EXPECT_EQ(stopped, -1);
  EXPECT_TRUE(passes.empty()) << passes;
  EXPECT_EQ(warned8.size(), 1u);
  const auto [quiet2, none] = quasi_static_run(0.02, 360, &stopped);  // 2 %: neither (transients outside the window)
  EXPECT_EQ(stopped, -1);
  EXPECT_TRUE(quiet2.empty()) << quiet2;
  EXPECT_TRUE(none.empty());
}

TEST(MassScaling, KineticEnergyLimitStopsASustainedExcessMidRun) {
  // 30 % from step 600 on: stopped once the excess has lasted 5 % of the 1000 expected steps (step 650),
  // not at the start transient (100 x for 20 steps, 2 %), and the end scan still reports it.
  long stopped = -1;
  std::string message;
  const auto [fails, warned] = quasi_static_run(0.3, 360, &stopped, &message);
  EXPECT_EQ(stopped, 650);
  EXPECT_NE(message.find("is 30 % of internal energy at step 650"), std::string::npos) << message;
  EXPECT_NE(message.find("above 'maximum kinetic energy ratio' 10 % of 'begin mass scaling' since step 600"),
            std::string::npos)
      << message;
  EXPECT_NE(fails.find("reached 30 % of internal energy at step 600"), std::string::npos) << fails;
  ASSERT_EQ(warned.size(), 1u);
}

// Mass damping keeps the unscaled run's damping force -c m0 v (docs/theory.md 1.4.1): one free element
// translating at v0, every element scaled by s = F^2 = 4, decays as m v' = -c m0 v, v = v0 exp(-c t / s);
// unscaled, as exp(-c t). The semi-implicit update gives v^{n+1/2} = (1 - a)/(1 + a) v^{n-1/2} with
// a = c h / (2 s), exp(-2a) to O(a^3) a step: 500 steps at c h = 0.01 (the first a half step, so v^{n+1/2}
// has decayed over 499.5 steps) are within 500 (2/3) a^3 = 4e-5 (a = 0.005) of the exponential: tolerance
// 1e-4, where the mass damping on the scaled masses would be 300 % off. The dissipation ledger counts the
// same force: KE0 - KE = damping_dissipation within 1 % (measured 78 J in both runs, c h E0,unscaled / 2:
// the pairing of the half first step with the initial velocity; a ledger on the scaled masses: 300 %).
TEST(MassScaling, MassDampingActsWithTheUnscaledMasses) {
  for (const bool scaled : {false, true}) {
    inputs::Deck deck = test::box_deck(1, 1.0, "elastic", inputs::ElementFormulation::mean_quadrature);
    auto& region = deck.procedure.region;
    const double v0 = 2.0;
    region.initial_velocities.push_back({"b_xmin", "", {0.0, 0.0, v0}, {}});
    region.initial_velocities.push_back({"b_xmax", "", {0.0, 0.0, v0}, {}});
    if (scaled) {
      region.mass_scaling = factor(2.0);
      region.mass_scaling->maximum_added_mass_fraction = 10.0;
    }
    const Model probe = build_model(deck);
    const double dt = 0.9 * compute_stable_time_step(probe, nullptr).dt;  // the run's step, scaled or not
    const double c = 0.01 / dt;                                            // 1/s
    region.mass_damping_coefficient = c;
    deck.procedure.time_control.termination_time = 1e4 * dt;
    Model model = build_model(deck);
    const double s = scaled ? 4.0 : 1.0;
    EXPECT_NEAR(sum(model.mass), s * 7800.0, 1e-9 * 7800.0);
    CentralDifference cd(model, deck.procedure.time_control);
    cd.init();
    const int steps = 500;
    for (int n = 0; n < steps; ++n) cd.step();
    ASSERT_NEAR(cd.time(), steps * dt, 1e-9 * dt);
    const double exact = v0 * std::exp(-c * (cd.time() - 0.5 * dt) / s);
    const char* label = scaled ? "scaled" : "unscaled";
    for (std::size_t node = 0; node < 8; ++node)
      EXPECT_NEAR(cd.velocity_half()[3 * node + 2], exact, 1e-4 * exact) << label << " node " << node;
    const Energies& e = cd.energies();
    std::printf("%s: v %.6e (exact %.6e), dissipated %.6e J, KE0 - KE %.6e J\n", label, cd.velocity_half()[2], exact,
                e.damping_dissipation, e.initial - e.kinetic);
    EXPECT_NEAR(e.damping_dissipation, e.initial - e.kinetic, 1e-2 * (e.initial - e.kinetic)) << label;
  }
}

}  // namespace
}  // namespace tribex::solver
