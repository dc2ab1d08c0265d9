// SPDX-License-Identifier: MIT
// `tribex pstd` end to end (no plots, small travel): determinism per seed, outputs with headers, exit code 2
// with a one-line message on bad input and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/cli/commands.hpp"
#include "mesh/mesh_error.hpp"
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
  EXPECT_THROW(tribex::cli::pstd_command({"--afm", std::string(TRIBEX_AFM_DATA_DIR) + "/matrix-3.txt",
                                          "--line", "999", "-o", o}),
               tribex::tools::BadInput);
  EXPECT_THROW(tribex::cli::pstd_command({"--segments", "6", "-o", o}), tribex::tools::BadInput);  // 12 um > 10 um
  EXPECT_THROW(tribex::cli::pstd_command({"--restoring", "-1", "--travel", "5nm", "--no-plots", "-o", o}),
               tribex::tools::BadInput);
  EXPECT_THROW(tribex::cli::pstd_command({"--channel", "0", "-o", o}), tribex::tools::BadInput);  // needs --afm
  EXPECT_THROW(tribex::cli::pstd_command({"deck.i", "-o", o}), tribex::tools::BadInput);  // options only
  EXPECT_THROW(tribex::cli::pstd_command({"--afm", std::string(TRIBEX_AFM_DATA_DIR) + "/di-1.di", "--channel",
                                          "99", "-o", o}),
               tribex::mesh::MeshError);
  EXPECT_THROW(tribex::cli::pstd_command({"--afm", std::string(TRIBEX_AFM_DATA_DIR) + "/README.md", "-o", o}),
               tribex::mesh::MeshError);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(tribex::cli::pstd_command({"--help"}), 0);
}

TEST(PstdCli, RunsOnALineOfANanoscopeAndAGsfMap) {
  // Any format mesh/afm reads. di-1.di: 512 px over 500 nm, so the periodic substrate is 0.5 um and the default
  // travel (the substrate length) at 0.5 nm sampling is 1000 steps; example_gsf.gsf: 256 px over 20 um.
  const auto base = std::filesystem::temp_directory_path() / "tribex_pstd_cli_afm";
  std::filesystem::remove_all(base);
  const std::string data = std::string(TRIBEX_AFM_DATA_DIR) + "/";
  ASSERT_EQ(tribex::cli::pstd_command({"--afm", data + "di-1.di", "--line", "100", "--segments", "2",
                                       "--segment-length", "200nm", "--sampling", "0.5nm", "--normal-force", "20uN",
                                       "--no-plots", "--quiet", "-o", (base / "di").string()}),
            0);
  const std::string di_json = slurp(base / "di" / "summary.json");
  EXPECT_NE(di_json.find("\"substrate\": \"di-1.di channel Height row 100\""), std::string::npos) << di_json;
  EXPECT_NE(di_json.find("\"substrate_length_um\": 0.5,"), std::string::npos) << di_json;
  EXPECT_NE(di_json.find("\"counterface_length_um\": 0.4,"), std::string::npos) << di_json;
  const std::string di_csv = slurp(base / "di" / "trajectory.csv");
  EXPECT_EQ(std::count(di_csv.begin(), di_csv.end(), '\n'), 1002);  // header + positions 0..500 nm by 0.5 nm

  ASSERT_EQ(tribex::cli::pstd_command({"--afm", data + "example_gsf.gsf", "--channel", "0", "--line", "10",
                                       "--travel", "1um", "--no-plots", "--quiet", "-o", (base / "gsf").string()}),
            0);
  const std::string gsf_json = slurp(base / "gsf" / "summary.json");
  EXPECT_NE(gsf_json.find("example_gsf.gsf channel Test image row 10"), std::string::npos) << gsf_json;
  EXPECT_NE(gsf_json.find("\"substrate_length_um\": 20,"), std::string::npos) << gsf_json;
  EXPECT_NE(gsf_json.find("\"counterface_length_um\": 6,"), std::string::npos) << gsf_json;
  const std::string gsf_csv = slurp(base / "gsf" / "trajectory.csv");
  EXPECT_EQ(std::count(gsf_csv.begin(), gsf_csv.end(), '\n'), 1002);  // header + positions 0..1000 nm
  std::filesystem::remove_all(base);
}
