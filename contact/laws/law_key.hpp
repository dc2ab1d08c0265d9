// SPDX-License-Identifier: MIT
// How a contact law declares its deck keys (beside the law, contact/laws/README.md): the deck schema,
// the deck builder's checks and the key reference are made from these declarations (KeyDecl, shared
// with the material models), and the values the deck gives reach the law's make() as KeyValues.
// Keys shared by several laws (the adhesion keys) are declared by each law that takes them, with the
// same unit. Here also what the laws share beyond their keys: LawProblem, LawError, format_line.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>

#include "inputs/keys/key_decl.hpp"

namespace tribex::contact {

// The deck keys of a law and the values the deck gives them: the declaration shared with the material
// models (inputs/keys/key_decl.hpp).
using keys::KeyDecl;
using keys::KeyValues;
using keys::optional_key;

/// What is wrong with a law's values: the deck key to point at ("" : the `model` line) and the
/// message with its fix (the caller adds FILE:LINE).
struct LawProblem {
  std::string key;
  std::string message;
};

/// printf into a string: the laws' run-log lines (describe()).
[[gnu::format(printf, 1, 2)]] inline std::string format_line(const char* format, ...) {
  std::va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  std::string out(static_cast<std::size_t>(std::max(std::vsnprintf(nullptr, 0, format, args), 0)), '\0');
  va_end(args);
  std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

/// Thrown by a law's make() when its values cannot be used (a summit file that cannot be read): `key`
/// the deck key to point at; `located` when the message already starts with FILE:LINE of that file.
struct LawError : std::invalid_argument {
  LawError(std::string key_, const std::string& message, bool located_ = false)
      : std::invalid_argument(message), key(std::move(key_)), located(located_) {}
  std::string key;
  bool located;
};

}  // namespace tribex::contact
