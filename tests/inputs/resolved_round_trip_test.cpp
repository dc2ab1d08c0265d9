// SPDX-License-Identifier: MIT
// Issue 29, item 3: the resolved deck that log.txt prints ("every default filled in, SI units") is a
// deck: for every valid deck in the repository it parses again, and resolving it again gives the same
// text (a fixed point). It failed for every contact deck ("'mean plane offset' applies to 'model =
// rough surface'").
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "inputs/diagnostics.hpp"

using namespace tribex::inputs;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> repository_decks() {
  std::vector<fs::path> decks;
  const fs::path root(TRIBEX_SOURCE_DIR);
  for (const char* dir : {"verification", "inputs/examples", "tools/bench", "tests/bad_decks/good", "tests/guards", "tests/fuzz/corpus"})
    for (const auto& e : fs::recursive_directory_iterator(root / dir))
      if (e.is_regular_file() && e.path().extension() == ".i") decks.push_back(e.path());
  return decks;
}

TEST(ResolvedDeck, EveryRepositoryDeckRoundTrips) {
  int contact_decks = 0, checked = 0;
  for (const auto& path : repository_decks()) {
    Deck deck;
    try {
      deck = parse_deck_file(path.string());
    } catch (const DeckError&) {
      continue;  // a deck made to fail (none in these folders today) is not a round-trip case
    }
    ++checked;
    if (deck.procedure.region.contact) ++contact_decks;
    // Parsed as if it were the file itself, so that relative paths (meshes, summit files) resolve alike.
    Deck again;
    try {
      again = parse_deck_string(deck.resolved_text, path.string());
    } catch (const DeckError& e) {
      ADD_FAILURE() << path << ": the resolved deck does not parse:\n" << e.what() << "\n" << deck.resolved_text;
      continue;
    }
    EXPECT_EQ(again.resolved_text, deck.resolved_text) << path << ": resolving the resolved deck changed it";
  }
  EXPECT_GE(checked, 40);
  EXPECT_GE(contact_decks, 20);
}

}  // namespace
