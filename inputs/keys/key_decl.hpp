// SPDX-License-Identifier: MIT
// How a material model (materials/) or a contact law (contact/laws/) declares a deck key of its own,
// and the values the deck gives those keys. One type for both lists: the deck schema, the deck
// builder's checks (own keys, required keys, a key of another model) and the key reference are made
// from these declarations by one code path (inputs/schema.cpp add_declared_keys,
// inputs/deck_builder.cpp declared_values), and a model reads its values by key name, never by
// position, so reordering its declared keys cannot mis-assign them.
// Header-only, and the ground layer: it includes nothing of tribex, and every layer may include it
// (docs/architecture.md "Dependency direction").
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tribex::keys {

struct KeyDecl {
  std::string_view key;           // deck key: lower case, words separated by one blank
  std::string_view unit;          // SI unit of the value ("Pa", "m", "J/m^2"); "" a pure number; "path" a file name
  double lower_bound = 0.0;       // the value must be above (open) or at least (closed) this (-INFINITY: none)
  bool lower_open = true;
  bool required = false;          // the deck must give it
  std::string_view help;          // one line for the key reference and error messages
  // Optional keys: the default in deck syntax ("0", "2 GPa"), filled in by the builder when the deck
  // does not give the key; "" leaves the key absent, and the model's make() applies the default that
  // `help` states (the contact laws, which ask has() to tell a given key from a default).
  std::string_view default_text = "";
};

/// The same key, optional (a law that takes another law's keys as an option: Coulomb's adhesion).
constexpr KeyDecl optional_key(KeyDecl key) {
  key.required = false;
  return key;
}

/// The values of a model's declared keys that the deck gives, with the declared defaults filled in
/// (SI; paths resolved against the deck's folder), by key name.
struct KeyValues {
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
  /// The value of a key that is always there (required, or declared with a default_text): a missing
  /// one is a programming error (a name the model did not declare), std::logic_error naming it.
  double at(std::string_view key) const {
    const auto it = numbers.find(key);
    if (it == numbers.end())
      throw std::logic_error("no value for key '" + std::string(key) + "': declare it required or with a default");
    return it->second;
  }
  std::string path(std::string_view key) const {
    const auto it = paths.find(key);
    return it == paths.end() ? std::string() : it->second;
  }
};

}  // namespace tribex::keys
