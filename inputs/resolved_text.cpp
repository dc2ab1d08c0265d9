// SPDX-License-Identifier: MIT
#include <charconv>
#include <cstdio>

#include "inputs/deck_builder.hpp"

namespace tribex::inputs {
namespace {

std::string number(double v) {
  char b[40];  // shortest text that reads back as the same double
  const auto r = std::to_chars(b, b + sizeof b, v);
  return std::string(b, r.ptr);
}

double unit_factor(const Scope& function, const std::string& key) {
  const KeyLine* k = function.find(key);
  return (k && k->value) ? k->value->numbers.at(0) : 1.0;
}

void emit(const Scope& s, const Scope* parent, int depth, std::string& out) {
  const std::string indent(static_cast<std::size_t>(2 * depth), ' ');
  const std::string header = s.type() + (s.name.empty() ? "" : " " + s.name);
  out += indent + "begin " + header + "\n";
  for (const auto& key : s.schema->keys) {
    if (!key.in_resolved_text) continue;
    if (key.repeatable) {
      for (const auto& k : s.keys)
        if (k.schema == &key && k.value) out += indent + "  " + key.name + " " + format_value(key, *k.value) + "\n";
      continue;
    }
    std::optional<Value> v;
    if (const KeyLine* k = s.find(key.name)) {
      v = k->value;
    } else {
      v = default_value(key);
    }
    if (v) out += indent + "  " + key.name + " = " + format_value(key, *v) + "\n";
  }
  if (s.schema->rows) {
    // The function's units are folded into the table, which is written in SI.
    const double fx = parent ? unit_factor(*parent, "abscissa unit") : 1.0;
    const double fy = parent ? unit_factor(*parent, "ordinate unit") : 1.0;
    for (const auto& r : s.rows) {
      out += indent + "  " + number(r.numbers[0] * fx) + " " + number(r.numbers[1] * fy) + "\n";
    }
  }
  for (const auto& c : s.children) emit(c, &s, depth + 1, out);
  out += indent + "end " + header + "\n";
}

}  // namespace

std::string resolved_text(const Scope& root) {
  std::string out = "# resolved deck: every default filled in, every number in SI units\n";
  for (const auto& c : root.children) emit(c, nullptr, 0, out);
  return out;
}

}  // namespace tribex::inputs
