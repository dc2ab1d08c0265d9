// SPDX-License-Identifier: MIT
// `tribex layered` through its command function: --help, a run's CSV and summary, bad arguments ending
// in one line and exit code 2 with nothing written; the continuum table read by `tribex fit`.
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
#include "tools/fit/coating_table.hpp"

namespace {

const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tribex_layered_cli_test";

std::pair<int, std::string> run(const std::vector<std::string>& args) {
  return tribex::test::run_capturing_stderr([&] { return tribex::cli::layered_command(args); });
}

const std::vector<std::string> case1 = {"--radius", "27nm", "--thickness", "2nm", "--layer-youngs", "8GPa",
                                        "--layer-poisson", "0.4", "--no-plot"};

std::vector<std::string> with(std::vector<std::string> head, const std::vector<std::string>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

TEST(LayeredCli, HelpAndARun) {
  EXPECT_EQ(run({"--help"}).first, 0);
  std::filesystem::remove_all(dir);
  const auto [code, err] = run(with(case1, {"--points", "20", "--pressure", "5", "-o", dir.string()}));
  ASSERT_EQ(code, 0) << err;
  std::ifstream csv(dir / "layered.csv");
  std::string line, header;
  int rows = 0;
  while (std::getline(csv, line)) {
    if (line.rfind("#", 0) == 0) continue;
    if (header.empty()) header = line; else ++rows;
  }
  EXPECT_EQ(header, "p_tilde[-],load[nN],contact_radius[nm],approach[nm],f[-],center_pressure[GPa]");
  EXPECT_EQ(rows, 20);
  EXPECT_TRUE(std::filesystem::exists(dir / "summary.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "pressure.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "layered.csv.tmp"));
}

TEST(LayeredCli, BadArgumentsExit2WithOneLineAndNothingWritten) {
  const std::filesystem::path out = dir / "bad";
  std::filesystem::remove_all(out);
  const std::vector<std::vector<std::string>> bad = {
      {"--thickness", "2nm", "--layer-youngs", "8GPa", "--layer-poisson", "0.4"},     // no radius
      {"--radius", "27nm"},                                                          // no layer
      {"--radius", "27nm", "--thickness", "2nm", "--layer-youngs", "8GPa", "--layer-poisson", "0.6"},  // nu >= 0.5
      {"--radius", "27nm", "--thickness", "2nm,1nm", "--layer-youngs", "8GPa", "--layer-poisson", "0.4"},
      with(case1, {"--spacing", "cubic"}),
      with(case1, {"--p-tilde", "1,0.5"}),
      with(case1, {"--rigid-base", "--substrate-youngs", "100GPa"}),
      with(case1, {"--thickness-typo", "3"}),
      with(case1, {"--p-tilde-file", "/nonexistent/loads.csv"}),
  };
  for (auto args : bad) {
    args.push_back("-o");
    args.push_back(out.string());
    const auto [code, err] = run(args);
    EXPECT_EQ(code, 2) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_FALSE(std::filesystem::exists(out)) << err;
  }
}

TEST(LayeredCli, TopLayerTooThinForTheContactIsANumericalFailure) {
  // a/h_top = 3 nm / 0.001 nm needs 18,000 Nystrom nodes: exit 3, one line, nothing written.
  const std::filesystem::path out = dir / "thin";
  std::filesystem::remove_all(out);
  const auto [code, err] = run({"--radius", "27nm", "--thickness", "0.001nm", "--layer-youngs", "8GPa", "--layer-poisson",
                                "0.4", "--loads", "50nN", "--no-plot", "-o", out.string()});
  EXPECT_EQ(code, 3) << err;
  EXPECT_NE(err.find("too thin"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(LayeredCli, ContinuumTableIsACoatingTable) {
  // verification/coated/reference.csv (compare_reference.py table) in `tribex fit friction --coating-table` form.
  const auto t = tribex::fit::CoatingTable::read(std::string(TRIBEX_SOURCE_DIR) + "/verification/coated/reference.csv");
  EXPECT_TRUE(t.covers(0.0560248));
  const auto c = t.at(0.0560248);  // case 1
  EXPECT_GT(c.A, 0.6);
  EXPECT_LT(c.A, 0.8);
  EXPECT_LT(c.b, -0.05);
  EXPECT_GT(c.b, -0.12);
}

}  // namespace
