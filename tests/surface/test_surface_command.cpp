// SPDX-License-Identifier: MIT
// `tribex surface` and `tribex gw` from the command line: every AFM sample gives a table; bad input exits 2.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "tools/cli/commands.hpp"
#include "tools/cli/error_mapping.hpp"

namespace {
const std::string afm_dir = std::string(TRIBEX_AFM_DATA_DIR) + "/";

int run_surface(const std::vector<std::string>& args) {
  return tribex::cli::run_mapping_errors([&] { return tribex::cli::surface_command(args); });
}
int run_gw(const std::vector<std::string>& args) {
  return tribex::cli::run_mapping_errors([&] { return tribex::cli::gw_command(args); });
}
}  // namespace

TEST(SurfaceCommand, EveryAfmSampleGivesAStatisticsTable) {
  for (const char* f : {"di-1.di", "di-2.di", "di-3.di", "di-5.di", "example_gsf.gsf", "matrix-3.txt"}) {
    EXPECT_EQ(run_surface({"stats", afm_dir + f, "--json"}), 0) << f;
  }
  EXPECT_EQ(run_surface({"stats", afm_dir + "di-1.di", "--channel", "1", "--window", "0,0,100nm,35nm", "--resample", "64",
                         "--median", "--smooth"}),
            0);
  EXPECT_EQ(run_surface({"mccool", afm_dir + "di-3.di", afm_dir + "matrix-3.txt", "--load", "10mN"}), 0);
  EXPECT_EQ(run_surface({"contact", afm_dir + "di-5.di", "--points", "5"}), 0);
}

TEST(SurfaceCommand, BadInputExitsTwo) {
  const std::string corrupt = ::testing::TempDir() + "/cut.di";
  {
    std::FILE* f = std::fopen(corrupt.c_str(), "wb");
    std::fputs("\\*File list\r\n\\Data length: 40960\r\n", f);
    std::fclose(f);
  }
  EXPECT_EQ(run_surface({"stats", corrupt}), 2);
  EXPECT_EQ(run_surface({"stats", afm_dir + "nope.di"}), 2);
  EXPECT_EQ(run_surface({"stats", afm_dir + "di-1.di", "--channel", "2"}), 2);  // Phase, not a height
  EXPECT_EQ(run_surface({"stats", afm_dir + "di-1.di", "--window", "0,0,1um,1um"}), 2);
  EXPECT_EQ(run_surface({"stats", afm_dir + "di-1.di", "--windw", "0,0,1nm,1nm"}), 2);
  EXPECT_EQ(run_surface({"mccool", afm_dir + "di-3.di", "--separation", "1", "--load", "1mN"}), 2);
  EXPECT_EQ(run_surface({"mccool", afm_dir + "di-3.di", "--E1", "12 m"}), 2);
  EXPECT_EQ(run_surface({"bogus"}), 2);
  EXPECT_EQ(run_gw({"fn", "--t-min", "5", "--t-max", "1"}), 2);
  EXPECT_EQ(run_gw({"curve", "--beta", "-1"}), 2);
  EXPECT_EQ(run_gw({"figures"}), 2);
}
