// SPDX-License-Identifier: MIT
// `model = frictionless`: penalty normal contact only (docs/theory.md 5.2), the pass applies it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "contact/laws/law_key.hpp"

namespace tribex::contact {

struct Frictionless {
  static constexpr std::string_view deck_name = "frictionless";
  static constexpr std::array<KeyDecl, 0> keys{};
  static constexpr bool penalty = true;    // penalty normal contact for g < 0
  static constexpr bool mortar = true;     // also with enforcement = mortar
  static constexpr int state_size = 0;     // doubles of state per slave node
  static constexpr bool reads_velocity = false;  // positions only (reads_velocity in contact_law.hpp)
  static std::optional<LawProblem> check(const KeyValues&) { return std::nullopt; }
  static Frictionless make(const KeyValues&) { return {}; }
  std::string describe() const { return "frictionless penalty contact"; }
  double reach() const { return 0.0; }     // gap beyond which the law does nothing, m
};

}  // namespace tribex::contact
