// SPDX-License-Identifier: MIT
// Static friction and adhesion (Eqs. 2.2-2.3) recovered from synthetic clamp-voltage ramps.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tools/cli/commands.hpp"

#include "tools/friction_test/static_friction.hpp"
#include "tools/common/errors.hpp"
#include "tools/friction_test/synth.hpp"

namespace tribex::friction_test {
namespace {

// Parallel plate, fringing neglected (as the report): with 0.24 mm^2 at a 2 um gap, 200 V gives
// 10.6 mN and 1.9 V gives ~1 uN, the report's range for L_c = 600 um.
TEST(StaticFriction, ClampForceMatchesTheReportRange) {
  ClampLoad c{2.4e-7, 2e-6};
  EXPECT_NEAR(c.normal_force(200.0), 10.6e-3, 0.05e-3);
  EXPECT_NEAR(c.normal_force(1.9), 1.0e-6, 0.05e-6);
  ClampLoad with_terms{2.4e-7, 2e-6, 1e-9, 0.5, 2e-6};  // + m g - k_z z (Eq. 2.3)
  EXPECT_NEAR(with_terms.normal_force(0.0), 1e-9 * standard_gravity - 1e-6, 1e-15);
}

struct StaticCase {
  const char* name;
  double stiffness, mu_s, mu_d, adhesion_force, noise;
  std::uint64_t seed;
};

class StaticRecovery : public ::testing::TestWithParam<StaticCase> {};

TEST_P(StaticRecovery, RecoversMuSAndAdhesionWithinUncertainty) {
  const auto c = GetParam();
  StaticSetup s;
  s.stiffness = c.stiffness;
  s.mu_s = c.mu_s;
  s.mu_d = c.mu_d;
  s.adhesion_force = c.adhesion_force;
  s.noise = c.noise;
  s.seed = c.seed;
  const tools::CsvRecord r = synth_static(s);
  const auto& v = r.voltage("voltage");
  const auto& x = r.column("position", inputs::dim::length);
  std::vector<double> fn;
  for (double volts : v) fn.push_back(s.clamp.normal_force(volts));
  const StaticFit f = fit_static(detect_slips(x, fn, s.stiffness, 0.0, 0.5e-6), c.name, 0.5e-6);
  EXPECT_GE(f.events.size(), 5u);
  // 3 sigma with fixed seeds; sigma itself must be at or below the report's +-0.01.
  EXPECT_NEAR(f.line.mu, c.mu_s, 3 * f.line.mu_sigma);
  EXPECT_LT(f.line.mu_sigma, 0.01);
  EXPECT_NEAR(f.line.adhesion_force, c.adhesion_force, 3 * f.line.adhesion_force_sigma);
  EXPECT_LT(f.line.adhesion_force_sigma, 0.1 * c.adhesion_force);
  for (const auto& e : f.events) EXPECT_LT(e.jump, 0.0);  // slips go back toward the spring zero
}

// FOTAS (report Fig. 2.6, Section 2.1.3): Load Spring A 4.5 N/m, mu_s 0.31 (and 0.34), mu_d 0.28,
// adhesion 1 nN/um^2 over a foot area taken as 4800 um^2 (the report gives no area): 4.8 uN.
INSTANTIATE_TEST_SUITE_P(Sets, StaticRecovery,
                         ::testing::Values(StaticCase{"fotas_10nm", 4.5, 0.31, 0.28, 4.8e-6, 10e-9, 11},
                                           StaticCase{"fotas_1nm", 4.5, 0.31, 0.28, 4.8e-6, 1e-9, 12},
                                           StaticCase{"fotas_034", 4.5, 0.34, 0.28, 4.8e-6, 10e-9, 13},
                                           StaticCase{"stiff_high_mu", 6.0, 0.6, 0.45, 12e-6, 10e-9, 14}));

TEST(StaticFriction, NoSlipIsBadInputWithAHint) {
  std::vector<double> x(50, 10e-6), fn(50, 1e-3);
  try {
    fit_static(detect_slips(x, fn, 4.5, 0.0, 0.5e-6), "ramp.csv", 0.5e-6);
    FAIL() << "expected BadInput";
  } catch (const tools::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("ramp.csv: no slip event found"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--min-jump"), std::string::npos);
  }
}

TEST(StaticFriction, JumpsAwayFromTheSpringZeroAreNotSlips) {
  std::vector<double> x{10e-6, 10e-6, 12e-6, 12e-6}, fn{3e-3, 2e-3, 1e-3, 0.5e-3};
  EXPECT_TRUE(detect_slips(x, fn, 4.5, 0.0, 0.5e-6).empty());
  std::vector<double> back{10e-6, 10e-6, 8e-6, 8e-6};
  const auto ev = detect_slips(back, fn, 4.5, 0.0, 0.5e-6);
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_DOUBLE_EQ(ev[0].friction_force, 4.5 * 10e-6);
  EXPECT_DOUBLE_EQ(ev[0].normal_force, 1.5e-3);
  EXPECT_DOUBLE_EQ(ev[0].load_resolution, 0.5e-3);
}

}  // namespace
}  // namespace tribex::friction_test

namespace tribex::friction_test {
namespace {

// A normal_force column is used as F_N directly; the --stiffness uncertainty adds to mu_s only.
TEST(StaticFriction, NormalForceColumnAndStiffnessUncertaintyThroughTheCommand) {
  StaticSetup s;
  s.seed = 17;
  const tools::CsvRecord r = synth_static(s);
  const auto& v = r.voltage("voltage");
  const auto& x = r.column("position", inputs::dim::length);
  std::vector<double> fn;
  for (double volts : v) fn.push_back(s.clamp.normal_force(volts));
  const auto dir = std::filesystem::temp_directory_path() / "tribex_friction_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "ramp_fn.csv").string();
  tools::CsvRecord(path, {{"normal_force", {fn, "uN"}}, {"position", {x, "nm"}}}).write(path);
  testing::internal::CaptureStdout();
  EXPECT_EQ(cli::friction_test_command({"static", path, "--stiffness", "4.5", "--stiffness-uncertainty", "0.045", "--json"}), 0);
  const std::string out = testing::internal::GetCapturedStdout();
  // mu_s uncertainty is dominated by the 1% stiffness error: 0.31 * 0.01 = 0.0031.
  EXPECT_NE(out.find("\"mu_s\": {\"value\": 0.31"), std::string::npos) << out;
  const auto at = out.find("\"mu_s\"");
  const auto unc = out.find("\"uncertainty\": ", at);
  const double mu_sigma = std::stod(out.substr(unc + 15));
  EXPECT_NEAR(mu_sigma, 0.0031, 0.0002);
}

// Reduced points (normal_force and friction_force, no position): the Eq. 2.2 line through them as
// given, no --stiffness; exact data F = 0.3 (N + 0.2 uN) return mu = 0.3 and F_adh = 0.2 uN.
TEST(StaticFriction, ReducedPointsAreFittedDirectly) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_friction_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "points.csv").string();
  std::vector<double> fn = {1e-6, 2e-6, 5e-6, 9e-6}, fs;  // SI, written in uN
  for (double n : fn) fs.push_back(0.3 * (n + 0.2e-6));
  tools::CsvRecord(path, {{"normal_force", {fn, "uN"}}, {"friction_force", {fs, "uN"}}}).write(path);
  testing::internal::CaptureStdout();
  EXPECT_EQ(cli::friction_test_command({"static", path, "--json"}), 0);
  const std::string out = testing::internal::GetCapturedStdout();
  const auto value = [&](const std::string& key) {
    const auto at = out.find("\"" + key + "\": {\"value\": ");
    EXPECT_NE(at, std::string::npos) << key << " in " << out;
    return at == std::string::npos ? NAN : std::stod(out.substr(at + key.size() + 13));
  };
  EXPECT_NEAR(value("mu_s"), 0.3, 1e-9);
  EXPECT_NEAR(value("adhesion_force"), 0.2e-6, 1e-15);
  EXPECT_NEAR(value("slip_events"), 4.0, 0.0);
}

// One CSV convention with `tribex fit`: a `load,friction` file (fit's synonyms) is the same reduced
// points; a file with neither points nor a position record names the missing column.
TEST(StaticFriction, FitsCsvConventionAndMissingColumnNamed) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_friction_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "load_friction.csv").string();
  {
    std::ofstream f(path);
    f << "load[uN],friction[uN]\n1,0.36\n2,0.66\n5,1.56\n9,2.76\n";  // F = 0.3 (N + 0.2 uN)
  }
  testing::internal::CaptureStdout();
  EXPECT_EQ(cli::friction_test_command({"static", path, "--json"}), 0);
  const std::string out = testing::internal::GetCapturedStdout();
  const auto at = out.find("\"mu_s\": {\"value\": ");
  ASSERT_NE(at, std::string::npos) << out;
  EXPECT_NEAR(std::stod(out.substr(at + 18)), 0.3, 1e-9);

  const std::string bad = (dir / "lateral.csv").string();
  {
    std::ofstream f(bad);
    f << "load[uN],lateral[uN]\n1,0.36\n2,0.66\n";
  }
  try {
    cli::friction_test_command({"static", bad});
    ADD_FAILURE() << "no error";
  } catch (const tools::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("lateral.csv:1: missing column 'friction_force'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribex::friction_test
