// SPDX-License-Identifier: MIT
// `tribex adhesion-curve` through its command function: --help, a run's files (CSV header, limits,
// valid summary keys), bad arguments ending in one line and exit code 2 with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tools/cli/commands.hpp"
#include "tests/support/cli_capture.hpp"

namespace {

const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tribex_adhesion_cli_test";

std::pair<int, std::string> run(const std::vector<std::string>& args) {
  return tribex::test::run_capturing_stderr([&] { return tribex::cli::adhesion_curve_command(args); });
}

std::string header_of(const std::filesystem::path& p, int& rows) {
  std::ifstream in(p);
  std::string line, header;
  rows = 0;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) continue;
    if (header.empty()) header = line; else ++rows;
  }
  return header;
}

TEST(AdhesionCli, HelpAndARun) {
  EXPECT_EQ(run({"--help"}).first, 0);
  std::filesystem::remove_all(dir);
  const auto [code, err] = run({"--tabor", "3", "--max-load-bar", "1", "--no-plot", "--json", "-o", dir.string()});
  ASSERT_EQ(code, 0) << err;
  int rows = 0;
  EXPECT_EQ(header_of(dir / "adhesion.csv", rows),
            "branch[-],approach[m],load[N],contact_radius[m],compressive_radius[m],bonded_radius[m],zone_radius[m],central_gap[m],min_gap[m],rings[-],"
            "approach_over_z0[-],load_bar[-],a_bar[-],approach_bar[-]");
  EXPECT_GT(rows, 100);
  EXPECT_EQ(header_of(dir / "limits.csv", rows),
            "a_bar[-],dmt_load_bar[-],dmt_approach_bar[-],jkr_load_bar[-],jkr_approach_bar[-],md_load_bar[-],md_approach_bar[-]");
  EXPECT_EQ(rows, 401);
  std::ifstream js(dir / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(js)), std::istreambuf_iterator<char>());
  for (const char* key : {"\"tabor\": 3", "\"pull_off_load_control\": {", "\"jump_out_displacement_control\": {",
                          "\"jump_in_displacement_control\": {", "\"captured_work_J_m2\"", "\"maugis_dugdale_pull_off_bar\""})
    EXPECT_NE(text.find(key), std::string::npos) << key << " in " << text;
  EXPECT_FALSE(std::filesystem::exists(dir / "adhesion.csv.tmp"));
}

TEST(AdhesionCli, BadArgumentsExit2WithOneLineAndNothingWritten) {
  const std::filesystem::path out = dir / "bad";
  std::filesystem::remove_all(out);
  const std::vector<std::vector<std::string>> bad = {
      {"--radius", "27nm", "--tabor", "1"},                // both
      {"--radius", "-1nm"},                                // negative radius
      {"--work", "0"},                                     // W = 0 without --max-load
      {"--z0", "0"},                                       // z0
      {"--cutoff", "0.3nm"},                               // cut-off below 1.5 z0
      {"--e-star", "85GPa", "--youngs", "161GPa"},         // both moduli
      {"--poisson", "0.5"},                                // nu
      {"--tabor", "100"},                                  // out of range
      {"--resolution", "1"},                               // too coarse
      {"--penalty", "1"},                                  // too soft
      {"--contact-gap", "0.1nm"},                          // >= 0.2 z0
      {"--max-load", "1nN", "--max-load-bar", "2"},        // both
      {"--radius", "27nm", "--wrok", "0.05"},              // unknown option
      {"--work", "5nm"},                                   // wrong dimension
  };
  for (auto args : bad) {
    args.insert(args.end(), {"--no-plot", "-o", out.string()});
    const auto [code, err] = run(args);
    EXPECT_EQ(code, 2) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_FALSE(std::filesystem::exists(out)) << err;
  }
}

}  // namespace
