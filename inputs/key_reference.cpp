// SPDX-License-Identifier: MIT
#include "inputs/key_reference.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace tribex::inputs {
namespace {

std::string value_type(const KeySchema& k) {
  const std::string unit = k.dimension == dim::none ? "" : " [" + k.dimension.str() + "]";
  const std::string count = k.count > 1 ? std::to_string(k.count) + " " : "";
  switch (k.kind) {
    case ValueKind::real: return "number" + unit;
    case ValueKind::reals: return count + "numbers" + unit;
    case ValueKind::integer: return "integer";
    case ValueKind::integers: return count + "integers";
    case ValueKind::string: return "name";
    case ValueKind::strings: return "names";
    case ValueKind::enumeration: return "one of: " + join_choices(k.allowed);
    case ValueKind::enumerations: return "any of: " + join_choices(k.allowed);
    case ValueKind::boolean: return "on/off";
    case ValueKind::unit: return k.any_dimension ? "unit" : "unit" + unit;
    case ValueKind::quantity: return "number with a unit";
  }
  return "";
}

// The blocks that list `type` among their children.
std::vector<std::string> parents_of(const std::string& type) {
  std::vector<std::string> out;
  for (const BlockSchema& b : all_block_schemas())
    if (b.child(type)) out.push_back(b.type.empty() ? "the file" : b.type);
  return out;
}

std::string name_rule(const BlockSchema& b) {
  switch (b.name) {
    case NameRule::none: return "no NAME";
    case NameRule::optional: return "optional NAME";
    case NameRule::required:
      return b.name_allowed.empty() ? "NAME required" : "NAME one of: " + join_choices(b.name_allowed);
  }
  return "";
}

std::string children(const BlockSchema& b) {
  std::string out;
  for (const ChildRule& c : b.children) {
    if (!out.empty()) out += ", ";
    out += c.type;
    if (c.min == 0 && c.max == unlimited) continue;
    out += " (";
    out += std::to_string(c.min);
    if (c.max == unlimited) {
      out += "+";
    } else if (c.max != c.min) {
      out += "-";
      out += std::to_string(c.max);
    }
    out += ")";
  }
  return out.empty() ? "none" : out;
}

void describe(std::ostringstream& o, const BlockSchema& b, bool markdown) {
  const auto parents = parents_of(b.type);
  if (markdown) {
    o << "## `begin " << b.type << "`\n\n" << b.help << "\n\n";
    o << "- " << name_rule(b) << "; inside: " << (parents.empty() ? std::string("the file") : join_choices(parents))
      << "; blocks inside: " << children(b) << (b.rows ? "; its lines are rows of numbers" : "") << "\n\n";
    if (b.keys.empty()) return;
    o << "| key | value | default | required | description |\n| --- | --- | --- | --- | --- |\n";
    for (const KeySchema& k : b.keys) {
      std::string help = k.help;
      std::replace(help.begin(), help.end(), '|', '/');
      o << "| `" << k.name << "` | " << value_type(k) << " | " << (k.default_text.empty() ? "-" : k.default_text) << " | "
        << (k.required ? "yes" : "") << " | " << help << " |\n";
    }
    o << "\n";
    return;
  }
  o << "begin " << b.type << "    (" << name_rule(b) << "; inside: " << (parents.empty() ? std::string("the file") : join_choices(parents))
    << ")\n  " << b.help << "\n  blocks inside: " << children(b) << "\n";
  for (const KeySchema& k : b.keys)
    o << "  " << k.name << (k.required ? " (required)" : "") << " = " << value_type(k)
      << (k.default_text.empty() ? "" : ", default " + k.default_text) << "\n      " << k.help << "\n";
  o << "\n";
}

}  // namespace

std::string key_reference(const BlockSchema* block, bool markdown) {
  std::ostringstream o;
  if (block) {
    describe(o, *block, markdown);
    return o.str();
  }
  if (markdown)
    o << "# Deck key reference\n\nGenerated from the schema (inputs/schema.cpp) by `tribex keys --markdown`; do not edit:\n"
         "the CTest `keys_reference_current` fails when this file and the schema differ. Units: numbers take a unit\n"
         "(`27 nm`, `0.1 J/m^2`); a plain number is SI. Parameters: a line `{W = 0.05 J/m^2}` defines W, `{W}` or\n"
         "`{2*W}` in a later value is replaced by its value (units and arithmetic `+ - * / ^ ( )`), and\n"
         "`tribex run|check DECK --set W=0.06` replaces a definition's value (inputs/README.md, \"Parameters\").\n"
         "The generated asperity's size limits: mesh/README.md, \"Asperity generator limits\". The blocks, in schema order:\n\n";
  for (const BlockSchema& b : all_block_schemas())
    if (!b.type.empty()) describe(o, b, markdown);
  return o.str();
}

}  // namespace tribex::inputs
