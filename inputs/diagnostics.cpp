// SPDX-License-Identifier: MIT
#include "inputs/diagnostics.hpp"

namespace tribex::inputs {

std::string Diagnostic::str() const {
  std::string s = where.str();
  s += ": error: ";
  s += message;
  if (!scope.empty()) {
    s += " [in ";
    s += scope;
    s += "]";
  }
  return s;
}

namespace {
std::string join(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) {
    if (!s.empty()) s += '\n';
    s += d.str();
  }
  return s;
}
}  // namespace

DeckError::DeckError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(join(diagnostics)), diagnostics_(std::move(diagnostics)) {}

}  // namespace tribex::inputs
