// SPDX-License-Identifier: MIT
// The run guards (solver/guards): a warning once at its first crossing with its maximum kept, limits
// that stop the run, the quasi-static window, and the restart round trip.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "solver/errors.hpp"
#include "solver/guards/run_guards.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {
namespace {

// Energies whose relative error is `error`: 1 J of external work, 1 - error J stored.
Energies with_error(double error) {
  Energies e;
  e.external_work = 1.0;
  e.internal = 1.0 - error;
  return e;
}

struct Said {
  std::vector<std::string> lines;
  std::function<void(const RunWarning&)> sink() {
    return [this](const RunWarning& w) { lines.push_back(w.message); };
  }
};

TEST(RunGuards, EnergyErrorWarnsOnceAtFirstCrossingAndKeepsTheMaximum) {
  inputs::GuardSpec spec;  // default warning at 1 %
  Said said;
  RunGuards g(spec, SetupFindings{}, 100, said.sink());
  g.observe(1, 1e-12, with_error(0.005), nullptr);
  EXPECT_TRUE(g.warnings().empty());
  g.observe(2, 2e-12, with_error(0.02), nullptr);
  g.observe(3, 3e-12, with_error(0.05), nullptr);
  g.observe(4, 4e-12, with_error(0.03), nullptr);
  ASSERT_EQ(g.warnings().size(), 1u);
  const RunWarning& w = g.warnings()[0];
  EXPECT_STREQ(kind_name(w.kind), "energy_error");
  EXPECT_EQ(w.step, 2);
  EXPECT_DOUBLE_EQ(w.time, 2e-12);
  EXPECT_NEAR(w.value, 0.02, 1e-12);
  EXPECT_DOUBLE_EQ(w.threshold, 0.01);
  EXPECT_NEAR(w.max_value, 0.05, 1e-12);
  EXPECT_EQ(w.max_step, 3);
  ASSERT_EQ(said.lines.size(), 1u);  // printed once, at the crossing
  EXPECT_NE(said.lines[0].find("energy balance error 2 % at step 2"), std::string::npos) << said.lines[0];
  EXPECT_NE(describe(w).find("largest 5 % at step 3"), std::string::npos) << describe(w);
}

// The energy warning names its likely source: the ledger term that changed most since the error was last
// below half the warning (solver/guards/README.md), the contact first when it gave the bodies energy.
TEST(RunGuards, EnergyErrorNamesTheContactWhenItGaveTheBodiesEnergy) {
  inputs::GuardSpec spec;
  Said said;
  RunGuards g(spec, SetupFindings{{}, "", "'sphere_flat'", true, {}}, 100, said.sink());
  Energies e = with_error(0.004);
  g.observe(1, 1e-12, e, nullptr);  // clean: below half the warning
  // The contact gives 0.3 J (contact_work falls), the viscosity takes 0.29 J of it out: the error grows.
  e.contact_work -= 0.3;
  e.viscous_dissipation += 0.29;
  e.internal += 0.03;
  g.observe(2, 2e-12, e, nullptr);
  ASSERT_EQ(g.warnings().size(), 1u);
  const RunWarning& w = g.warnings()[0];
  EXPECT_EQ(w.source, EnergySource::contact);
  EXPECT_NEAR(w.source_change, 0.3, 1e-12);
  EXPECT_EQ(w.since_step, 1);
  EXPECT_STREQ(source_name(w.source), "contact_work");
  for (const char* part : {"likely source: the contact (interaction 'sphere_flat') gave 0.3 J", "since step 1",
                           "lower 'largest factor'"})
    EXPECT_NE(w.message.find(part), std::string::npos) << part << " in: " << w.message;
}

TEST(RunGuards, EnergyErrorNamesTheLargestChangeOtherwise) {
  inputs::GuardSpec spec;
  Said said;
  RunGuards g(spec, SetupFindings{{}, "", "'i'", false, {}}, 100, said.sink());
  Energies e = with_error(0.0);
  g.observe(1, 1e-12, e, nullptr);
  e.hourglass += 0.05;  // the hourglass stores energy nobody put in
  e.contact_work += 0.001;  // the contact absorbed a little: not a source
  g.observe(2, 2e-12, e, nullptr);
  ASSERT_EQ(g.warnings().size(), 1u);
  EXPECT_EQ(g.warnings()[0].source, EnergySource::hourglass);
  EXPECT_NE(g.warnings()[0].message.find("likely source: hourglass energy grew 0.05 J since step 1"), std::string::npos)
      << g.warnings()[0].message;
}

TEST(RunGuards, EnergyErrorLimitStopsTheRun) {
  inputs::GuardSpec spec;
  spec.energy_error_limit = 0.1;
  Said said;
  RunGuards g(spec, SetupFindings{}, 100, said.sink());
  g.observe(1, 1e-12, with_error(0.05), nullptr);
  EXPECT_THROW(g.observe(2, 2e-12, with_error(0.2), nullptr), NumericalFailure);
  ASSERT_EQ(g.warnings().size(), 1u);  // the warning is in the list the summary writes
  EXPECT_NEAR(g.warnings()[0].max_value, 0.2, 1e-12);
}

TEST(RunGuards, ContactPenetrationAndMotionNameTheNode) {
  inputs::GuardSpec spec;
  Said said;
  RunGuards g(spec, SetupFindings{}, 100, said.sink());
  contact::ContactTotals c;
  c.max_penetration_ratio = 0.1;
  c.penetration_node = 41;
  c.motion_ratio = 0.2;
  g.observe(1, 1e-12, with_error(0.0), &c);
  EXPECT_TRUE(g.warnings().empty());
  c.max_penetration_ratio = 0.3;
  c.motion_ratio = 0.7;
  c.motion_node = 7;
  g.observe(2, 2e-12, with_error(0.0), &c);
  ASSERT_EQ(g.warnings().size(), 2u);
  EXPECT_STREQ(kind_name(g.warnings()[0].kind), "penetration");
  EXPECT_EQ(g.warnings()[0].node, 41);
  EXPECT_NE(g.warnings()[0].message.find("node 42"), std::string::npos);  // 1-based in messages
  EXPECT_STREQ(kind_name(g.warnings()[1].kind), "contact_motion");
  c.motion_ratio = 1.5;  // past the default limit 1: tunnelling stops the run
  try {
    g.observe(3, 3e-12, with_error(0.0), &c);
    FAIL() << "no NumericalFailure past the contact motion limit";
  } catch (const NumericalFailure& e) {
    EXPECT_NE(std::string(e.what()).find("tunnelling"), std::string::npos) << e.what();
  }
}

// Quasi-static: kinetic / internal energy is checked where the internal energy is at least 10 % of its
// peak, so the approach (internal energy ~ 0) and the unloaded end do not count.
TEST(RunGuards, QuasiStaticChecksTheLoadedPartOnly) {
  inputs::GuardSpec spec;
  spec.quasi_static = true;  // kinetic energy warning 5 %
  Said said;
  {
    RunGuards g(spec, SetupFindings{}, 1000, said.sink());
    for (long n = 0; n < 1000; ++n) {
      Energies e;
      e.internal = n < 500 ? 1e-3 * n : 1e-3 * (1000 - n);  // load and unload, peak 0.5
      e.kinetic = 0.01;                                     // huge against the first rows, 2 % at the peak
      e.external_work = e.kinetic + e.internal;             // a balanced ledger
      g.observe(n, 1e-12 * n, e, nullptr);
    }
    g.finish();
    // Rows with internal >= 0.05: kinetic / internal up to 0.01 / 0.05 = 20 %.
    ASSERT_EQ(g.warnings().size(), 1u);
    const RunWarning& w = g.warnings()[0];
    EXPECT_STREQ(kind_name(w.kind), "kinetic_energy");
    EXPECT_NEAR(double(w.step), 50.0, 1.0);  // the first loaded row (internal energy 0.05 = 10 % of 0.5)
    EXPECT_NEAR(w.value, 0.2, 0.005);
    EXPECT_NEAR(w.max_value, 0.2, 0.005);
  }
  {
    RunGuards g(spec, SetupFindings{}, 1000, said.sink());
    for (long n = 0; n < 1000; ++n) {
      Energies e;
      e.internal = n < 500 ? 1e-3 * n : 1e-3 * (1000 - n);
      e.kinetic = n < 20 ? 1.0 : 1e-3;  // a start transient, then 2 % of the lowest loaded internal energy
      e.external_work = e.kinetic + e.internal;      g.observe(n, 1e-12 * n, e, nullptr);
    }
    g.finish();
    EXPECT_TRUE(g.warnings().empty());
  }
}

TEST(RunGuards, SetUpWarningsOpenTheListAndRestartKeepsRunWarnings) {
  inputs::GuardSpec spec;
  RunWarning setup;
  setup.kind = WarningKind::adhesion_cutoff;
  setup.message = "deck.i:12: cut-off";
  Said said;
  RunGuards g(spec, SetupFindings{{setup}, "", "", false, {}}, 100, said.sink());
  g.observe(5, 5e-12, with_error(0.03), nullptr);
  g.observe(6, 6e-12, with_error(0.04), nullptr);
  StateArchive archive;
  g.save(archive);

  RunGuards resumed(spec, SetupFindings{{setup}, "", "", false, {}}, 100, said.sink());
  resumed.restore(archive);
  resumed.observe(7, 7e-12, with_error(0.06), nullptr);
  ASSERT_EQ(resumed.warnings().size(), 2u);
  EXPECT_EQ(resumed.warnings()[0].message, "deck.i:12: cut-off");
  const RunWarning& w = resumed.warnings()[1];
  EXPECT_EQ(w.step, 5);  // the first crossing of the earlier segment
  EXPECT_EQ(w.max_step, 7);
  EXPECT_NEAR(w.max_value, 0.06, 1e-12);
}

// One-point elements under node-to-face penalty contact: raised only once the penetration passes 0.1
// element sizes (high pressure), naming the interaction and blocks found at set-up.
TEST(RunGuards, OnePointContactIsRaisedAtHighPressureOnly) {
  inputs::GuardSpec spec;
  Said said;
  RunGuards g(spec, SetupFindings{{}, "deck.i:9:9: interaction 'i' on block 'tip'", "'i'", false, {}}, 100, said.sink());
  contact::ContactTotals c;
  c.max_penetration_ratio = 0.05;
  c.penetration_node = 3;
  g.observe(1, 1e-12, with_error(0.0), &c);
  EXPECT_TRUE(g.warnings().empty());
  c.max_penetration_ratio = 0.12;
  g.observe(2, 2e-12, with_error(0.0), &c);
  ASSERT_EQ(g.warnings().size(), 1u);
  EXPECT_STREQ(kind_name(g.warnings()[0].kind), "unsafe_choice");
  EXPECT_NE(g.warnings()[0].message.find("interaction 'i' on block 'tip'"), std::string::npos);
  RunGuards without(spec, SetupFindings{}, 100, said.sink());  // no one-point contact: only the general guard
  without.observe(2, 2e-12, with_error(0.0), &c);
  EXPECT_TRUE(without.warnings().empty());
}

}  // namespace
}  // namespace tribex::solver
