// SPDX-License-Identifier: MIT
// `tribex pstd` end to end (no plots, small travel): determinism per seed, outputs with headers, exit code 2
// with a one-line message on bad input and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/cli/commands.hpp"
#include "tools/common/errors.hpp"

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(PstdCli, SameSeedGivesIdenticalOutput) {
  const auto base = std::filesystem::temp_directory_path() / "tribex_pstd_cli_test";
  std::filesystem::remove_all(base);
  const std::vector<std::string> common{"--travel", "2um", "--seed", "5", "--copies", "2", "--study", "--no-plots", "--quiet"};
  auto with_out = [&](const std::string& dir) {
    auto v = common;
    v.push_back("-o");
    v.push_back((base / dir).string());
    return v;
  };
  ASSERT_EQ(tribex::cli::pstd_command(with_out("a")), 0);
  ASSERT_EQ(tribex::cli::pstd_command(with_out("b")), 0);
  const std::string a = slurp(base / "a" / "trajectory.csv");
  EXPECT_EQ(a, slurp(base / "b" / "trajectory.csv"));
  EXPECT_EQ(slurp(base / "a" / "area_study.csv").substr(0, 60), slurp(base / "b" / "area_study.csv").substr(0, 60));
  EXPECT_EQ(a.rfind("position[nm],displacement[um],normal_force_arrival[uN]", 0), 0u);
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 2002);  // header + positions 0..2000 nm
  EXPECT_TRUE(std::filesystem::exists(base / "a" / "summary.json"));
  std::filesystem::remove_all(base);
}

TEST(PstdCli, BadInputIsRejectedBeforeAnythingIsWritten) {
  const auto out = std::filesystem::temp_directory_path() / "tribex_pstd_cli_bad";
  std::filesystem::remove_all(out);
  const std::string o = out.string();
  EXPECT_THROW(tribex::cli::pstd_command({"--law", "4d", "-o", o}), tribex::tools::BadInput);
  EXPECT_THROW(tribex::cli::pstd_command({"--normal-forse", "1mN", "-o", o}), tribex::tools::BadInput);
  EXPECT_THROW(tribex::cli::pstd_command({"--normal-force", "1 GPa", "-o", o}), tribex::tools::BadInput);
  EXPECT_THROW(tribex::cli::pstd_command({"--afm", std::string(TRIBEX_SHARED_DIR) + "/data/afm/matrix-3.txt",
                                          "--line", "999", "-o", o}),
               tribex::tools::BadInput);
  EXPECT_THROW(tribex::cli::pstd_command({"--segments", "6", "-o", o}), tribex::tools::BadInput);  // 12 um > 10 um
  EXPECT_THROW(tribex::cli::pstd_command({"--restoring", "-1", "--travel", "5nm", "--no-plots", "-o", o}),
               tribex::tools::BadInput);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(tribex::cli::pstd_command({"--help"}), 0);
}
