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

  void error(const SourceLocation& where, std::string scope, std::string message) {
    if (diagnostics_.size() < max_diagnostics) {
      diagnostics_.push_back({where, std::move(scope), std::move(message)});
    } else {
      ++suppressed_;
    }
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
