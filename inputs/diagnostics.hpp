// SPDX-License-Identifier: MIT
// Deck errors: every problem found in a deck becomes one Diagnostic; the parser collects them
// all and throws one DeckError (exit code 2 at the command line, nothing written).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "inputs/deck.hpp"

namespace tribex::inputs {

struct Diagnostic {
  SourceLocation where;
  std::string scope;    // e.g. "sierra/presto procedure/presto region"; may be empty
  std::string message;  // one line: the problem and the fix
  /// "FILE:LINE:COL: error: MESSAGE [in SCOPE]"
  std::string str() const;
};

class DeckError : public std::runtime_error {
 public:
  explicit DeckError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

/// Parse and validate a deck file (following `include FILE` lines relative to the including
/// file). `settings` replace the values of the deck's parameters (`--set`; inputs/parameters.hpp).
/// Throws DeckError with every problem found.
Deck parse_deck_file(const std::string& path, const std::vector<ParameterSetting>& settings = {});

/// The same for deck text already in memory; `file_name` is used in messages and to resolve
/// relative paths (include, database name).
Deck parse_deck_string(const std::string& text, const std::string& file_name,
                       const std::vector<ParameterSetting>& settings = {});

}  // namespace tribex::inputs
