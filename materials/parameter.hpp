// SPDX-License-Identifier: MIT
// How a material model declares the deck keys of its own parameters (beyond the elastic constants
// every model takes): the deck schema, the builder and the key reference are made from these
// (inputs/schema.cpp, inputs/deck_builder.cpp), so a model declares its keys once, beside its law.
#pragma once

#include <array>
#include <string_view>

namespace tribex::materials {

struct ParameterDecl {
  std::string_view key;           // deck key: lower case, words separated by one blank
  std::string_view unit;          // SI unit of the value ("Pa"); "" for a dimensionless number
  double lower_bound = 0.0;       // the value must be above (open) or at least (closed) this
  bool lower_open = false;
  std::string_view default_text;  // in deck syntax; "" means the key is required
  std::string_view help;          // one line for the key reference and error messages
};

/// What the hyperelastic models share: no keys beyond E and nu, no state, no dissipation
/// (materials/README.md lists the interface).
struct Hyperelastic {
  static constexpr std::array<ParameterDecl, 0> parameters{};
  static constexpr int state_size = 0;
  static constexpr bool dissipates = false;
};

}  // namespace tribex::materials
