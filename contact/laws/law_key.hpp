// SPDX-License-Identifier: MIT
// How a contact law declares its deck keys (beside the law, contact/laws/README.md): the deck schema,
// the deck builder's checks and the key reference are made from these declarations, and the values
// the deck gives reach the law's make() as LawValues. Keys shared by several laws (the adhesion keys)
// are declared by each law that takes them, with the same unit.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tribex::contact {

struct LawKey {
  std::string_view key;       // deck key: lower case, words separated by one blank
  std::string_view unit;      // SI unit of the value ("Pa", "m", "J/m^2"); "" a pure number; "path" a file name
  double lower_bound = 0.0;   // the value must be above (open) or at least (closed) this
  bool lower_open = true;
  bool required = false;      // the law needs it (else the law's default, stated in `help`)
  std::string_view help;      // one line for the key reference and error messages
};

/// The same key, optional (a law that takes another law's keys as an option: Coulomb's adhesion).
constexpr LawKey optional_key(LawKey key) {
  key.required = false;
  return key;
}

/// The values of a law's keys that the deck gives (SI; paths resolved against the deck's folder).
struct LawValues {
  std::map<std::string, double, std::less<>> numbers;
  std::map<std::string, std::string, std::less<>> paths;
  bool has(std::string_view key) const { return numbers.count(key) > 0 || paths.count(key) > 0; }
  double get(std::string_view key, double fallback) const {
    const auto it = numbers.find(key);
    return it == numbers.end() ? fallback : it->second;
  }
  std::optional<double> find(std::string_view key) const {
    const auto it = numbers.find(key);
    return it == numbers.end() ? std::nullopt : std::optional<double>(it->second);
  }
  std::string path(std::string_view key) const {
    const auto it = paths.find(key);
    return it == paths.end() ? std::string() : it->second;
  }
};

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
