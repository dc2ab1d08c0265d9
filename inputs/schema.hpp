// SPDX-License-Identifier: MIT
// The declarative description of the deck language: every block TYPE, where it may stand, how
// often, whether it takes a NAME, and every key with its value kind, dimension, range, default
// and allowed values. Adding a key or a block for a later feature is an edit of the table in
// schema.cpp (plus reading the value in deck_builder.cpp); the tree builder, the value checks,
// the error messages and the resolved text all follow the table.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "inputs/units.hpp"

namespace tribex::inputs {

enum class ValueKind {
  real,          // one number with a unit of `dimension` (plain numbers are SI)
  reals,         // `count` numbers sharing one trailing unit: `size = 100 20 20 nm`
  integer,       // one integer
  integers,      // `count` integers
  string,        // a name (the words of the value joined by one blank; case kept)
  strings,       // one or more names
  enumeration,   // one of `allowed` (case-insensitive; the words joined: "piecewise linear")
  enumerations,  // one or more of `allowed`, no repeats
  boolean,       // on/off/true/false/yes/no
  unit,          // a unit expression such as `ps` (checked against `dimension` unless any_dimension)
  quantity,      // one number with a unit of any dimension (checked where it is used)
};

/// A closed/open interval for numbers; default: everything finite.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string str() const;  // "> 0", ">= 1", "in (-1, 0.5)", "in (0, 1]"
};

struct KeySchema {
  std::string name;  // lower case, words separated by one blank
  ValueKind kind = ValueKind::real;
  Dimension dimension = dim::none;
  Range range;
  int count = 1;  // reals/integers: exact count
  std::vector<std::string> allowed;                             // enumeration(s)
  std::vector<std::pair<std::string, std::string>> aliases;     // alias -> allowed value
  bool required = false;
  std::string default_text;  // in deck syntax; empty: no default (optional key stays unset)
  bool any_dimension = false;  // unit keys: the dimension is checked where the value is used
  bool in_resolved_text = true;  // false: folded into other values in the resolved text
  bool repeatable = false;       // may be given on several lines (`contact surface A contains ...`)
  std::string help;
};

inline constexpr int unlimited = std::numeric_limits<int>::max();

/// A child block allowed inside a block, with how many of it may (must) appear.
struct ChildRule {
  std::string type;
  int min = 0;
  int max = unlimited;
};

enum class NameRule { none, required, optional };

struct BlockSchema {
  std::string type;  // lower case, words separated by one blank
  NameRule name = NameRule::none;
  std::vector<std::string> name_allowed;                            // non-empty: the NAME is an enum
  std::vector<std::pair<std::string, std::string>> name_aliases;    // alias -> allowed name
  bool unique_names = true;  // two blocks of this type with one NAME are an error
  std::vector<KeySchema> keys;
  std::vector<ChildRule> children;
  bool rows = false;  // a table of numbers (`begin values`): lines are rows, not keys
  std::string help;

  const KeySchema* key(std::string_view name) const;
  const ChildRule* child(std::string_view type) const;
};

/// The pseudo-block holding the whole file (its only child is `sierra`).
const BlockSchema& root_schema();

/// The schema of a block TYPE (lower case), or nullptr.
const BlockSchema* find_block_schema(std::string_view type);

/// Every block schema (for tests and documentation).
const std::vector<BlockSchema>& all_block_schemas();

/// Canonical form of an allowed value: lower case, aliases resolved; "" if not allowed.
std::string canonical_choice(std::string_view value, const std::vector<std::string>& allowed,
                             const std::vector<std::pair<std::string, std::string>>& aliases);

/// "a, b or c".
std::string join_choices(const std::vector<std::string>& allowed);

}  // namespace tribex::inputs
