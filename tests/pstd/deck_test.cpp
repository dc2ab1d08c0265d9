// SPDX-License-Identifier: MIT
// `tribex pstd DECK.i`: keys become options, input paths resolve from the deck's folder, command-line options
// override the deck, and every deck error names deck:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tools/cli/commands.hpp"
#include "tools/common/errors.hpp"
#include "tools/pstd/deck.hpp"

namespace {
const auto dir = std::filesystem::temp_directory_path() / "tribex_pstd_deck_test";

std::string write(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir);
  const auto p = (dir / name).string();
  std::ofstream(p) << text;
  return p;
}

std::string error_of(const std::vector<std::string>& args) {
  try {
    tribex::cli::pstd_command(args);
  } catch (const tribex::tools::BadInput& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(PstdDeck, KeysBecomeOptionsAndPathsResolveFromTheDeck) {
  const std::string deck = write("a.i",
                                 "# comment\nBEGIN PSTD\n  substrate file = sub.csv  # a file next to the deck\n"
                                 "  Normal Force = 2.2 mN\n  study = yes\n  plots no\n  output = out\nend pstd\n");
  const auto d = tribex::pstd::read_deck(deck);
  const std::vector<std::string> expected{"--substrate-file", (dir / "sub.csv").string(), "--normal-force", "2.2 mN",
                                          "--study", "--no-plots", "-o", "out"};
  EXPECT_EQ(d.args, expected);
  EXPECT_EQ(d.where.at("--normal-force"), deck + ":4");
}

TEST(PstdDeck, ErrorsNameTheDeckLine) {
  const std::string typo = write("typo.i", "begin pstd\n  normal forse = 1 mN\nend\n");
  EXPECT_EQ(error_of({typo}), typo + ":2: unknown key 'normal forse' (did you mean 'normal force'?); "
                                     "tribex pstd --help lists the deck keys");
  const std::string unit = write("unit.i", "begin pstd\n  travel = 5 nm\n  normal force = 2 GPa\nend\n");
  EXPECT_EQ(error_of({unit}).rfind(unit + ":3: ", 0), 0u) << error_of({unit});
  // The command line overrides the deck, and then the error is the command line's.
  EXPECT_EQ(error_of({unit, "--normal-force", "3 GPa"}).rfind("tribex pstd --normal-force", 0), 0u);
  const std::string open = write("open.i", "begin pstd\n  travel = 5 nm\n");
  EXPECT_EQ(error_of({open}), open + ":1: 'begin pstd' has no matching 'end'");
  const std::string twice = write("twice.i", "begin pstd\n seed = 1\n seed = 2\nend\n");
  EXPECT_EQ(error_of({twice}), twice + ":3: key 'seed' was already given on line 2");
  EXPECT_EQ(error_of({(dir / "missing.i").string()}), (dir / "missing.i").string() + ": cannot open the deck; check the path");
  std::filesystem::remove_all(dir);
}
