// SPDX-License-Identifier: MIT
// Collects every Diagnostic of one parse (bounded: a garbage deck must give a short report, not
// thousands of lines) and throws them together as one DeckError at the end.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "inputs/diagnostics.hpp"

namespace tribex::inputs {

class DiagnosticSink {
 public:
  /// More than this many errors in one deck are summarised by one final line.
  static constexpr std::size_t max_diagnostics = 50;

  /// A word of the deck echoed in a message is cut when longer than this (issue 54, item 16: a 7 MB token
  /// was echoed as one 7 MB line): its first kEchoKept characters and its length are kept.
  static constexpr std::size_t kEchoLimit = 200, kEchoKept = 80;

  void error(const SourceLocation& where, std::string scope, std::string message) {
    if (diagnostics_.size() < max_diagnostics) {
      diagnostics_.push_back({where, std::move(scope), shorten_words(std::move(message))});
    } else {
      ++suppressed_;
    }
  }
  /// `message` with every run of non-blank characters over kEchoLimit cut to kEchoKept (at a UTF-8
  /// character boundary) and "...[N characters]".
  static std::string shorten_words(std::string message) {
    std::string out;
    std::size_t i = 0;
    while (i < message.size()) {
      std::size_t j = i;
      while (j < message.size() && message[j] != ' ' && message[j] != '\n') ++j;
      if (j - i > kEchoLimit) {
        std::size_t keep = kEchoKept;
        while (keep > 0 && (static_cast<unsigned char>(message[i + keep]) & 0xC0) == 0x80) --keep;
        out.append(message, i, keep).append("...[" + std::to_string(j - i) + " characters]");
      } else {
        out.append(message, i, j - i);
      }
      if (j < message.size()) out.push_back(message[j]);
      i = j + 1;
    }
    return out;
  }
  bool empty() const { return diagnostics_.empty(); }
  std::size_t size() const { return diagnostics_.size() + suppressed_; }

  /// Throws DeckError if anything was reported.
  void throw_if_any() {
    if (diagnostics_.empty()) return;
    if (suppressed_ > 0) {
      Diagnostic last = diagnostics_.back();
      last.message = std::to_string(suppressed_) + " further errors not shown; fix the ones above first";
      last.scope.clear();
      diagnostics_.push_back(std::move(last));
      suppressed_ = 0;
    }
    throw DeckError(std::move(diagnostics_));
  }

 private:
  std::vector<Diagnostic> diagnostics_;
  std::size_t suppressed_ = 0;
};

}  // namespace tribex::inputs
