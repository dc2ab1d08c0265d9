// SPDX-License-Identifier: MIT
// `tribex fit` through its command function: synth -> friction --json end to end (values, PNG),
// and bad CSVs and arguments ending in one-line messages with exit code 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "tools/cli/commands.hpp"
#include "tools/cli/error_mapping.hpp"
#include "tools/common/errors.hpp"

namespace tribex::fit {
namespace {

const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tribex_fit_cli_test";

std::string write_temp(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

const std::vector<std::string> dmt_options = {"--model", "dmt", "--radius", "27nm", "--reduced-modulus", "84.1GPa"};

std::vector<std::string> with(std::vector<std::string> head, const std::vector<std::string>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

// Runs the command like the front end does; returns the exit code and the BadInput message.
std::pair<int, std::string> run(const std::vector<std::string>& args) {
  try {
    return {cli::fit_command(args), ""};
  } catch (const tools::BadInput& e) {
    testing::internal::CaptureStderr();
    const int rc = cli::run_mapping_errors([&] { return cli::fit_command(args); });
    testing::internal::GetCapturedStderr();
    return {rc, e.what()};
  }
}

double json_value(const std::string& json, const std::string& key) {
  std::smatch m;
  const std::regex re("\"" + key + "\": \\{\"value\": ([-0-9.eE+]+)");
  if (!std::regex_search(json, m, re)) return NAN;
  return std::stod(m[1]);
}

TEST(FitCli, SynthThenFitRecoversValuesAndDrawsThePlot) {
  const auto csv = (dir / "dmt.csv").string();
  const auto png = (dir / "dmt.png").string();
  std::filesystem::create_directories(dir);
  std::filesystem::remove(png);
  testing::internal::CaptureStderr();
  ASSERT_EQ(cli::fit_command(with({"synth", "-o", csv, "--tau", "100MPa", "--W", "0.05J/m^2", "--loads", "-6nN,30nN",
                                   "--noise", "0.05", "--seed", "4"},
                                  dmt_options)),
            0);
  testing::internal::CaptureStdout();
  const int rc = cli::fit_command(with({"friction", csv, "--json", "-o", png, "--residual", "relative"}, dmt_options));
  const std::string out = testing::internal::GetCapturedStdout();
  testing::internal::GetCapturedStderr();
  ASSERT_EQ(rc, 0);
  const std::regex sigma_re("\"tau\": \\{\"value\": [-0-9.eE+]+, \"uncertainty\": ([-0-9.eE+]+)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, sigma_re)) << out;
  const double tau = json_value(out, "tau"), tau_sigma = std::stod(m[1]);
  EXPECT_LT(std::abs(tau - 100e6), 2 * tau_sigma) << out;
  EXPECT_NEAR(json_value(out, "W"), 0.05, 0.01) << out;
  EXPECT_NE(out.find("\"correlation\": [[1, "), std::string::npos) << out;
  if (std::filesystem::exists("/usr/bin/python3")) {
    EXPECT_TRUE(std::filesystem::exists(png));
  }
  EXPECT_FALSE(std::filesystem::exists(png + ".panel0.csv"));  // temporaries removed
}

// The coated model end to end with the study's own table (verification/coated/results.csv):
// synth at E_c = 8 GPa, then fit; tau* and W come back within 2 sigma.
TEST(FitCli, CoatedWithTheStudysTable) {
  const std::string table = TRIBEX_SOURCE_DIR "/verification/coated/results.csv";
  const auto csv = (dir / "coated.csv").string();
  std::filesystem::create_directories(dir);
  const std::vector<std::string> coated = {"--radius", "27nm", "--coating-table", table, "--coating-youngs", "8GPa"};
  testing::internal::CaptureStderr();
  ASSERT_EQ(cli::fit_command(with({"synth", "-o", csv, "--tau", "194MPa", "--W", "0.05J/m^2", "--loads=-6nN,40nN",
                                   "--noise", "0.05", "--seed", "5"},
                                  coated)),
            0);
  testing::internal::CaptureStdout();
  const int rc = cli::fit_command(with({"friction", csv, "--json", "--no-plot", "--residual", "relative"}, coated));
  const std::string out = testing::internal::GetCapturedStdout();
  testing::internal::GetCapturedStderr();
  ASSERT_EQ(rc, 0);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex("\"tau\": \\{\"value\": [-0-9.eE+]+, \"uncertainty\": ([-0-9.eE+]+)")))
      << out;
  const double tau_sigma = std::stod(m[1]);
  ASSERT_TRUE(std::regex_search(out, m, std::regex("\"W\": \\{\"value\": [-0-9.eE+]+, \"uncertainty\": ([-0-9.eE+]+)")))
      << out;
  const double w_sigma = std::stod(m[1]);
  EXPECT_LT(std::abs(json_value(out, "tau") - 194e6), 2 * tau_sigma) << out;
  EXPECT_LT(std::abs(json_value(out, "W") - 0.05), 2 * w_sigma) << out;
}

TEST(FitCli, HelpAndUnknownSubcommand) {
  testing::internal::CaptureStdout();
  EXPECT_EQ(cli::fit_command({"friction", "--help"}), 0);
  EXPECT_NE(testing::internal::GetCapturedStdout().find("usage: tribex fit friction"), std::string::npos);
  EXPECT_EQ(run({"frction"}).first, 2);
}

struct BadCase {
  std::string name, csv, expect;
  std::vector<std::string> extra;
};

TEST(FitCli, BadCsvAndArgumentsExitTwoWithOneLineMessage) {
  std::string good = "load[nN],friction[nN]\n";
  for (int i = 0; i < 10; ++i) good += std::to_string(-5 + 3 * i) + "," + std::to_string(2 + 0.3 * i) + "\n";
  const BadCase cases[] = {
      {"missing_column.csv", "load[nN],lateral[nN]\n1,2\n2,3\n3,4\n4,5\n5,6\n", "missing column 'friction_force' (the header has: normal_force,lateral", {}},
      {"load_in_nm.csv", "load[nm],friction[nN]\n1,2\n2,3\n3,4\n4,5\n5,6\n", "column 'load' (read as 'normal_force') has unit [nm] but needs a N unit", {}},
      {"both_names.csv", "load[nN],normal_force[nN],friction[nN]\n1,1,2\n", "both_names.csv:1: column 'normal_force' appears twice", {}},
      {"bad_unit.csv", "load[-nN],friction[nN]\n1,2\n2,3\n3,4\n4,5\n5,6\n", "bad_unit.csv:1: unit [-nN]", {}},
      {"too_few.csv", "load[nN],friction[nN]\n1,2\n2,3\n3,4\n", "3 data rows, at least 4 needed", {}},
      {"negative_friction.csv", "load[nN],friction[nN]\n1,2\n2,-3\n3,4\n4,5\n5,6\n",
       "negative_friction.csv:3: friction", {}},
      {"not_a_number.csv", "load[nN],friction[nN]\n1,2\n2,x\n3,4\n4,5\n5,6\n", "not_a_number.csv:3:", {}},
      {"same_load.csv", "load[nN],friction[nN]\n1,2\n1,3\n1,4\n1,5\n1,6\n", "fewer than 3 distinct", {}},
      {"good.csv", good, "unknown --model 'dtm'", {"--model", "dtm"}},
      {"good.csv", good, "--model md needs exactly one of --lambda", {"--model", "md"}},
      // (an explicit missing path: the default verification/coated/results.csv exists from the repository root)
      {"good.csv", good, "no_such_table.csv: coating table not found",
       {"--model", "coated", "--coating-table", (dir / "no_such_table.csv").string()}},
      {"good.csv", good, "--residual must be absolute or relative", {"--model", "dmt", "--residual", "log"}},
  };
  for (const auto& c : cases) {
    const auto path = write_temp(c.name, c.csv);
    std::vector<std::string> args = {"friction", path, "--no-plot", "--radius", "27nm"};
    if (c.extra.empty()) args.insert(args.end(), {"--model", "dmt"});
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const auto [rc, msg] = run(args);
    EXPECT_EQ(rc, 2) << c.name;
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.name << ": " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << c.name;
  }
  // The radius is required.
  EXPECT_NE(run({"friction", write_temp("good.csv", good), "--model", "dmt"}).second.find("--radius R is required"),
            std::string::npos);
}

}  // namespace
}  // namespace tribex::fit
