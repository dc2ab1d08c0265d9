// SPDX-License-Identifier: MIT
// The two lists whose members declare their own deck keys (inputs/keys/key_decl.hpp): the material models
// (materials/material.hpp, `begin parameters for model NAME`) and the contact laws
// (contact/laws/contact_law.hpp, `model = NAME` in `begin interaction`). The schema (schema.cpp
// add_declared_keys) and the builder (deck_builder.cpp declared_values) treat both the same way
// through this view of a list.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "contact/laws/contact_law.hpp"
#include "inputs/keys/key_decl.hpp"
#include "materials/material.hpp"

namespace tribex::inputs {

/// A list of models with their declared keys, in the list's order.
struct ModelList {
  std::vector<std::string> names;                   // deck names
  std::vector<std::span<const keys::KeyDecl>> keys;  // [model] its declared keys
};

// The names and keys of the models a registry's for_each visits (materials::for_each_model,
// contact::for_each_law), in registration order.
template <class ForEach>
ModelList model_list(ForEach for_each) {
  ModelList list;
  for_each([&](auto m, int) {
    using M = typename decltype(m)::type;
    list.names.emplace_back(M::deck_name);
    list.keys.emplace_back(M::keys);
  });
  return list;
}

inline ModelList material_model_list() {
  return model_list([](auto visit) { materials::for_each_model(visit); });
}

inline ModelList contact_law_list() {
  return model_list([](auto visit) { contact::for_each_law(visit); });
}

}  // namespace tribex::inputs
