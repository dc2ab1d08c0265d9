// SPDX-License-Identifier: MIT
// Every tests/bad_decks/*.i must fail with a diagnostic at the line and with the text its first
// line announces (`# expect: LINE: SUBSTRING`); every tests/bad_decks/good/*.i must parse.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "inputs/check_deck.hpp"
#include "inputs/diagnostics.hpp"

namespace fs = std::filesystem;
using namespace tribex::inputs;

namespace {

std::vector<std::string> decks_in(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(folder)) {
    if (e.is_regular_file() && e.path().extension() == ".i") out.push_back(e.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

const fs::path bad_dir = fs::path(TRIBEX_SOURCE_DIR) / "tests" / "bad_decks";

class BadDeck : public ::testing::TestWithParam<std::string> {};

TEST_P(BadDeck, FailsAtTheAnnouncedLineWithTheAnnouncedMessage) {
  const std::string path = (bad_dir / GetParam()).string();
  std::ifstream in(path, std::ios::binary);
  std::string first;
  std::getline(in, first);
  const std::string tag = "# expect: ";
  ASSERT_EQ(first.rfind(tag, 0), 0u) << path << ": first line must be '# expect: LINE: SUBSTRING'";
  const std::string rest = first.substr(tag.size());
  const auto colon = rest.find(": ");
  ASSERT_NE(colon, std::string::npos) << path;
  const int line = std::stoi(rest.substr(0, colon));
  const std::string substring = rest.substr(colon + 2);

  try {
    parse_deck_file(path);
    FAIL() << path << " parsed without error";
  } catch (const DeckError& e) {
    const auto& ds = e.diagnostics();
    const bool found = std::any_of(ds.begin(), ds.end(), [&](const Diagnostic& d) {
      return d.where.file == path && d.where.line == line && d.message.find(substring) != std::string::npos;
    });
    EXPECT_TRUE(found) << "expected '" << path << ":" << line << ": ... " << substring << "', got:\n" << e.what();
    // Bounded output: a bad deck gives a handful of lines, never hundreds.
    EXPECT_LE(ds.size(), 10u) << e.what();
    // The checker reports the same.
    EXPECT_EQ(check_deck_file(path).size(), ds.size());
  }
}

INSTANTIATE_TEST_SUITE_P(AllBadDecks, BadDeck, ::testing::ValuesIn(decks_in(bad_dir)),
                         [](const auto& p) { return fs::path(p.param).stem().string(); });

class GoodDeck : public ::testing::TestWithParam<std::string> {};

TEST_P(GoodDeck, Parses) {
  const std::string path = (bad_dir / "good" / GetParam()).string();
  EXPECT_TRUE(check_deck_file(path).empty());
  EXPECT_NO_THROW(parse_deck_file(path));
}

INSTANTIATE_TEST_SUITE_P(AllGoodDecks, GoodDeck, ::testing::ValuesIn(decks_in(bad_dir / "good")),
                         [](const auto& p) { return fs::path(p.param).stem().string(); });

TEST(BadDecks, ThereAreAtLeastTwenty) { EXPECT_GE(decks_in(bad_dir).size(), 20u); }

}  // namespace
