// SPDX-License-Identifier: MIT
#include "inputs/deck.hpp"

#include <algorithm>

namespace tribex::inputs {

std::string SourceLocation::str() const {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

namespace {
template <class T>
const T* find_named(const std::vector<T>& items, const std::string& name) {
  auto it = std::find_if(items.begin(), items.end(), [&](const T& t) { return t.name == name; });
  return it == items.end() ? nullptr : &*it;
}
}  // namespace

const FunctionSpec* Deck::find_function(const std::string& n) const { return find_named(functions, n); }
const MaterialSpec* Deck::find_material(const std::string& n) const { return find_named(materials, n); }
const SectionSpec* Deck::find_section(const std::string& n) const { return find_named(sections, n); }
const FiniteElementModelSpec* Deck::find_model(const std::string& n) const { return find_named(models, n); }

}  // namespace tribex::inputs
