// SPDX-License-Identifier: MIT
// libFuzzer target for the deck parser: any bytes must give a Deck or a DeckError, never a
// crash, a hang, unbounded memory or another exception. Built only with -DTRIBEX_FUZZ=ON (clang).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "inputs/diagnostics.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // A file name in a folder that does not exist: `include` lines cannot reach real files.
    const auto deck = tribex::inputs::parse_deck_string(text, "/nonexistent-fuzz-dir/fuzz.i");
    // The resolved text of an accepted deck must be accepted and resolve to itself.
    std::string again;
    try {
      again = tribex::inputs::parse_deck_string(deck.resolved_text, "/nonexistent-fuzz-dir/resolved.i").resolved_text;
    } catch (const tribex::inputs::DeckError& e) {
      std::fprintf(stderr, "resolved text rejected:\n%s\n---\n%s\n", e.what(), deck.resolved_text.c_str());
      std::abort();
    }
    if (again != deck.resolved_text) {
      std::fprintf(stderr, "resolved text not stable:\n%s\n---\n%s\n", deck.resolved_text.c_str(), again.c_str());
      std::abort();
    }
  } catch (const tribex::inputs::DeckError&) {
    // expected for almost every input
  }
  return 0;
}
