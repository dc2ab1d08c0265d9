// SPDX-License-Identifier: MIT
// The line-oriented lexer of the deck language: files -> logical lines of words.
//
//  - `#` and `$` start a comment (mid-line only when preceded by a blank, so `a#b` is one word);
//  - a line ending in `\` (or `\#`, `\$`, as in Sierra) continues on the next line;
//  - commas and tabs are blanks; `=` is always a word of its own ("a=1" -> "a" "=" "1");
//  - `include FILE` splices FILE (relative to the including file) in place, recursively; a
//    missing file, a non-regular file or an include cycle is an error at the include line;
//  - a file holding NUL bytes or invalid UTF-8 gives one error (its first bad byte) and is skipped.
// Every word keeps its file:line:col for messages.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "inputs/deck.hpp"
#include "inputs/diagnostic_sink.hpp"

namespace tribex::inputs {

struct Word {
  std::string text;
  SourceLocation where;
};

/// One logical line (continuations joined), never empty.
struct LogicalLine {
  std::vector<Word> words;
  const SourceLocation& where() const { return words.front().where; }
};

/// Limits that keep memory bounded on hostile input.
struct LexerLimits {
  std::size_t max_file_bytes = 8u << 20;    // per file: a deck is a short text file
  std::size_t max_total_bytes = 16u << 20;  // all files of one deck (one file may be included often)
  int max_include_depth = 32;
};

/// Lex deck text already in memory; `file_name` is used in locations and as the base for
/// relative include paths.
std::vector<LogicalLine> lex_deck_text(std::string_view text, const std::string& file_name, DiagnosticSink& sink,
                                       const LexerLimits& limits = {});

/// Read and lex a deck file; an unreadable file is a diagnostic at `file_name:0:0`.
std::vector<LogicalLine> lex_deck_file(const std::string& file_name, DiagnosticSink& sink,
                                       const LexerLimits& limits = {});

/// Index of the first byte that is NUL or not part of valid UTF-8, or npos.
std::size_t first_invalid_byte(std::string_view text);

/// ASCII lower case (keywords are case-insensitive).
std::string lower(std::string_view s);

}  // namespace tribex::inputs
