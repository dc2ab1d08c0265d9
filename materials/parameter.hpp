// SPDX-License-Identifier: MIT
// How a material model declares the deck keys of its own parameters (beyond the elastic constants
// every model takes): `static constexpr std::array<KeyDecl, N> keys`, the declaration shared with the
// contact laws (inputs/keys/key_decl.hpp). The deck schema, the builder and the key reference are made from
// these (inputs/schema.cpp add_declared_keys, inputs/deck_builder.cpp declared_values), so a model
// declares its keys once, beside its law, and reads the deck's values by name in make() (KeyValues:
// the builder has filled in every declared default).
#pragma once

#include <array>
#include <string_view>

#include "inputs/keys/key_decl.hpp"

namespace tribex::materials {

using keys::KeyDecl;
using keys::KeyValues;

/// What the hyperelastic models share: no keys beyond E and nu, no state, no dissipation
/// (materials/README.md lists the interface).
struct Hyperelastic {
  static constexpr std::array<KeyDecl, 0> keys{};
  static constexpr int state_size = 0;
  static constexpr bool dissipates = false;
};

}  // namespace tribex::materials
