// SPDX-License-Identifier: MIT
// Typed values of key lines: the words after the key are checked against the key's schema
// (kind, dimension, count, range, allowed values) and converted to SI.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "inputs/lexer.hpp"
#include "inputs/schema.hpp"
#include "inputs/units.hpp"

namespace tribex::inputs {

struct Value {
  std::vector<double> numbers;     // real(s), integer(s), quantity, unit (its factor to SI); SI
  std::vector<std::string> words;  // string(s) and enumeration(s), canonical form
  bool flag = false;               // boolean
  Dimension dimension;             // quantity / unit: the dimension written (none for plain numbers)
  bool has_unit = false;           // quantity: a unit was written
};

/// Converts the value words of one key line; on a problem reports it to `sink` (at the word at
/// fault, with `scope` for the message) and returns nullopt.
std::optional<Value> convert_value(const KeySchema& key, const std::vector<Word>& words,
                                   const SourceLocation& key_where, const std::string& scope, DiagnosticSink& sink);

/// The schema default of a key, converted; nullopt when the key has no default.
std::optional<Value> default_value(const KeySchema& key);

/// The value in deck syntax, numbers in SI in their shortest exact form (round-trips).
std::string format_value(const KeySchema& key, const Value& value);

/// "a length (m)", "a pressure (Pa)", "dimensionless", "a quantity in kg^1 m^2 s^-1".
std::string describe_dimension(const Dimension& d);

/// Parses a plain number (no unit) with std::from_chars; nullopt if the whole word is not one.
std::optional<double> plain_number(const std::string& word);

}  // namespace tribex::inputs
