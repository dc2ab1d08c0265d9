// SPDX-License-Identifier: MIT
// Bad records and arguments end in one-line tools::BadInput messages naming file:line and the
// fix, which the front end maps to exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tools/cli/commands.hpp"
#include "tools/cli/error_mapping.hpp"
#include "tools/common/errors.hpp"

namespace tribex::friction_test {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_friction_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string message_of(const std::vector<std::string>& args) {
  try {
    cli::friction_test_command(args);
  } catch (const tools::BadInput& e) {
    return e.what();
  }
  return "(no error)";
}

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "message: " << text << "\nexpected to contain: " << part;
  EXPECT_EQ(text.find('\n'), std::string::npos) << "one line: " << text;
}

TEST(FrictionTestBadInput, MissingColumnNamesTheHeader) {
  const auto f = write_temp("missing.csv", "time[s],pos[nm]\n0,1\n1,2\n");
  expect_contains(message_of({"calibrate", f, "--json"}), f + ":1: missing column 'position'");
}

TEST(FrictionTestBadInput, NonMonotonicTimeNamesTheLine) {
  const auto f = write_temp("backwards.csv", "time[s],position[nm]\n0,1\n2,2\n1,3\n");
  expect_contains(message_of({"dynamic", f, "--stiffness", "0.38"}), f + ":4: column 'time' does not increase");
}

TEST(FrictionTestBadInput, NonNumericCellNamesTheLine) {
  const auto f = write_temp("text.csv", "time[s],position[nm]\n0,1\n1,abc\n");
  expect_contains(message_of({"calibrate", f}), f + ":3: column 'position': 'abc' is not a number");
}

TEST(FrictionTestBadInput, WrongUnitDimensionIsRejected) {
  const auto f = write_temp("unit.csv", "time[nm],position[nm]\n0,1\n1,2\n");
  expect_contains(message_of({"calibrate", f}), "column 'time' has unit [nm] but needs a s unit");
}

TEST(FrictionTestBadInput, TooFewPoints) {
  const auto f = write_temp("short.csv", "time[s],position[nm]\n0,1\n1,2\n");
  expect_contains(message_of({"dynamic", f, "--mass", "2.25ug"}), "2 data rows, at least 30 needed");
}

TEST(FrictionTestBadInput, NoSlipEventInAStaticRamp) {
  std::string text = "voltage[V],position[um]\n";
  for (int i = 0; i < 50; ++i) text += std::to_string(100 - i) + ",40\n";
  const auto f = write_temp("noslip.csv", text);
  expect_contains(message_of({"static", f, "--stiffness", "4.5", "--gap", "2um", "--area", "0.24mm^2"}),
                  f + ": no slip event found");
}

TEST(FrictionTestBadInput, RaggedRowAndMissingFile) {
  const auto f = write_temp("ragged.csv", "time[s],position[nm]\n0,1\n1\n");
  expect_contains(message_of({"calibrate", f}), f + ":3: 1 cells but the header has 2 columns");
  expect_contains(message_of({"calibrate", "/nonexistent/x.csv"}), "/nonexistent/x.csv: cannot open the file");
}

TEST(FrictionTestBadInput, ArgumentsAreChecked) {
  expect_contains(message_of({"frobnicate"}), "unknown subcommand 'frobnicate'");
  const auto f = write_temp("any.csv", "time[s],position[nm]\n0,1\n");
  expect_contains(message_of({"dynamic", f}), "give exactly one of --stiffness");
  expect_contains(message_of({"dynamic", f, "--stiffness", "0.38", "--normal-force", "1nN,2nN"}),
                  "--normal-force has 2 value(s) for 1 file(s)");
  expect_contains(message_of({"static", f, "--stiffnes", "4.5"}), "--stiffnes");
}

TEST(FrictionTestBadInput, FrontEndMapsToExitCodeTwo) {
  const auto f = write_temp("backwards2.csv", "time[s],position[nm]\n0,1\n2,2\n1,3\n");
  EXPECT_EQ(cli::run_mapping_errors([&] { return cli::friction_test_command({"calibrate", f}); }), 2);
  EXPECT_EQ(cli::run_mapping_errors([&] { return cli::friction_test_command({"calibrate", "--help"}); }), 0);
}

}  // namespace
}  // namespace tribex::friction_test
