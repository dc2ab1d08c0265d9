// SPDX-License-Identifier: MIT
// GCC 12 reports a false -Wrestrict inside std::string operator+ (GCC bug 105651) for the
// message building below; the code is correct, so silence it for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include "inputs/values.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace tribex::inputs {
namespace {

std::string format_number(double v) {
  char b[40];  // shortest text that reads back as the same double
  const auto r = std::to_chars(b, b + sizeof b, v);
  return std::string(b, r.ptr);
}

std::string joined(const std::vector<Word>& words, std::size_t from = 0) {
  std::string s;
  for (std::size_t i = from; i < words.size(); ++i) {
    if (i > from) s += ' ';
    s += words[i].text;
  }
  return s;
}

struct Converter {
  const KeySchema& key;
  const std::vector<Word>& words;
  const SourceLocation& key_where;
  const std::string& scope;
  DiagnosticSink& sink;

  std::nullopt_t fail(const SourceLocation& where, const std::string& message) const {
    sink.error(where, scope, "'" + key.name + "': " + message);
    return std::nullopt;
  }
  const SourceLocation& first() const { return words.empty() ? key_where : words.front().where; }

  // Checks a quantity's dimension against the key's: plain numbers are SI of the key.
  bool dimension_ok(const Quantity& q, bool had_unit, const SourceLocation& where) const {
    if (!had_unit || q.dimension == key.dimension) return true;
    fail(where, "expected " + describe_dimension(key.dimension) + ", got " + describe_dimension(q.dimension) +
                    "; write a number with a unit of " + describe_dimension(key.dimension) +
                    " or a plain SI number");
    return false;
  }

  bool range_ok(double v, const SourceLocation& where) const {
    if (key.range.contains(v)) return true;
    char b[40];
    std::snprintf(b, sizeof b, "%g", v);
    fail(where, std::string("value ") + b + " is out of range: must be " + key.range.str());
    return false;
  }

  std::optional<Value> numbers() const {
    // `count` numbers, each plain or with its own unit, optionally followed by one unit word
    // that applies to every plain number ("100 20 20 nm"); "27nm" and "27 nm" both work.
    const int count = key.kind == ValueKind::real ? 1 : key.count;
    if (words.empty()) return fail(key_where, "missing value; expected " + std::to_string(count) + " number(s)");
    std::vector<Quantity> qs;
    std::vector<bool> had_unit;
    std::size_t i = 0;
    std::string error;
    for (; i < words.size() && static_cast<int>(qs.size()) < count; ++i) {
      auto q = parse_quantity(words[i].text, &error);
      if (!q) return fail(words[i].where, error + "; expected " + std::to_string(count) + " number(s)" +
                                              (key.dimension == dim::none ? "" : " with an optional unit"));
      had_unit.push_back(!plain_number(words[i].text).has_value());
      qs.push_back(*q);
    }
    if (static_cast<int>(qs.size()) < count) {
      return fail(first(), "expected " + std::to_string(count) + " numbers, got " + std::to_string(qs.size()));
    }
    if (i < words.size()) {
      // One trailing unit shared by all plain numbers.
      if (i + 1 < words.size()) {
        return fail(words[i + 1].where, "unexpected '" + words[i + 1].text + "' after the value; expected " +
                                            std::to_string(count) + " number(s) and an optional unit");
      }
      auto u = parse_unit(words[i].text, &error);
      if (!u) {
        if (plain_number(words[i].text)) {
          return fail(words[i].where, "expected " + std::to_string(count) + " number(s), got more");
        }
        return fail(words[i].where, error);
      }
      for (std::size_t k = 0; k < qs.size(); ++k) {
        if (had_unit[k]) return fail(words[i].where, "unit given twice; write the unit once at the end");
        qs[k].value *= u->value;
        qs[k].dimension = u->dimension;
        had_unit[k] = true;
      }
    }
    Value v;
    for (std::size_t k = 0; k < qs.size(); ++k) {
      const auto& where = k < words.size() ? words[k].where : first();
      if (key.kind == ValueKind::quantity) {
        v.dimension = qs[k].dimension;
        v.has_unit = had_unit[k];
      } else if (!dimension_ok(qs[k], had_unit[k], where)) {
        return std::nullopt;
      }
      if (!std::isfinite(qs[k].value)) return fail(where, "value overflows in SI units");
      if (!range_ok(qs[k].value, where)) return std::nullopt;
      v.numbers.push_back(qs[k].value);
    }
    return v;
  }

  std::optional<Value> integer_values() const {
    const int count = key.kind == ValueKind::integer ? 1 : key.count;
    if (static_cast<int>(words.size()) != count) {
      return fail(words.empty() ? key_where : words.front().where,
                  "expected " + std::to_string(count) + " integer(s), got " + std::to_string(words.size()) +
                      " word(s): '" + joined(words) + "'");
    }
    Value v;
    for (const auto& w : words) {
      long long n = 0;
      const char* b = w.text.data();
      const char* e = b + w.text.size();
      if (b != e && *b == '+') ++b;
      auto [ptr, ec] = std::from_chars(b, e, n);
      if (ec != std::errc{} || ptr != e || b == e || n < -2000000000LL || n > 2000000000LL) {
        return fail(w.where, "'" + w.text + "' is not an integer");
      }
      if (!range_ok(static_cast<double>(n), w.where)) return std::nullopt;
      v.numbers.push_back(static_cast<double>(n));
    }
    return v;
  }

  std::optional<Value> choices() const {
    if (words.empty()) return fail(key_where, "missing value; allowed: " + join_choices(key.allowed));
    Value v;
    if (key.kind == ValueKind::enumeration) {
      const std::string c = canonical_choice(joined(words), key.allowed, key.aliases);
      if (c.empty()) {
        return fail(first(), "'" + joined(words) + "' is not allowed; allowed: " + join_choices(key.allowed));
      }
      v.words.push_back(c);
      return v;
    }
    for (const auto& w : words) {
      const std::string c = canonical_choice(w.text, key.allowed, key.aliases);
      if (c.empty()) return fail(w.where, "'" + w.text + "' is not allowed; allowed: " + join_choices(key.allowed));
      for (const auto& seen : v.words) {
        if (seen == c) return fail(w.where, "'" + w.text + "' is listed twice; list each once");
      }
      v.words.push_back(c);
    }
    return v;
  }

  std::optional<Value> convert() const {
    switch (key.kind) {
      case ValueKind::real:
      case ValueKind::reals:
      case ValueKind::quantity:
        return numbers();
      case ValueKind::integer:
      case ValueKind::integers:
        return integer_values();
      case ValueKind::string: {
        if (words.empty()) return fail(key_where, "missing value; expected a name");
        Value v;
        v.words.push_back(joined(words));
        return v;
      }
      case ValueKind::strings: {
        if (words.empty()) return fail(key_where, "missing value; expected one or more names");
        Value v;
        for (const auto& w : words) v.words.push_back(w.text);
        return v;
      }
      case ValueKind::enumeration:
      case ValueKind::enumerations:
        return choices();
      case ValueKind::boolean: {
        if (words.size() != 1) return fail(first(), "expected one of on, off, true, false, yes, no");
        const std::string w = lower(words[0].text);
        Value v;
        if (w == "on" || w == "true" || w == "yes") {
          v.flag = true;
        } else if (w == "off" || w == "false" || w == "no") {
          v.flag = false;
        } else {
          return fail(words[0].where, "'" + words[0].text + "' is not a boolean; use on/off, true/false or yes/no");
        }
        return v;
      }
      case ValueKind::unit: {
        if (words.size() != 1) return fail(first(), "expected one unit such as ps, nm or GPa");
        std::string error;
        auto u = parse_unit(words[0].text, &error);
        if (!u) return fail(words[0].where, error);
        if (!key.any_dimension && u->dimension != key.dimension) {
          return fail(words[0].where, "expected a unit of " + describe_dimension(key.dimension) + ", got " +
                                          describe_dimension(u->dimension));
        }
        Value v;
        v.numbers.push_back(u->value);
        v.dimension = u->dimension;
        v.has_unit = true;
        return v;
      }
    }
    return std::nullopt;
  }
};

}  // namespace

std::optional<double> plain_number(const std::string& word) {
  double v = 0.0;
  const char* b = word.data();
  const char* e = b + word.size();
  if (b != e && *b == '+') ++b;
  auto [ptr, ec] = std::from_chars(b, e, v);
  if (ec != std::errc{} || ptr != e || b == e || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string describe_dimension(const Dimension& d) {
  struct Named {
    Dimension d;
    const char* name;
  };
  static const Named names[] = {
      {dim::none, "a dimensionless number"}, {dim::length, "a length (m)"},
      {dim::area, "an area (m^2)"},          {dim::time, "a time (s)"},
      {dim::rate, "a rate (1/s)"},           {dim::velocity, "a velocity (m/s)"},
      {dim::force, "a force (N)"},           {dim::pressure, "a pressure (Pa)"},
      {dim::energy, "an energy (J)"},        {dim::energy_per_area, "an energy per area (J/m^2)"},
      {dim::density, "a density (kg/m^3)"},  {dim::mass, "a mass (kg)"},
  };
  for (const auto& n : names) {
    if (n.d == d) return n.name;
  }
  return "a quantity in " + d.str();
}

std::optional<Value> convert_value(const KeySchema& key, const std::vector<Word>& words,
                                   const SourceLocation& key_where, const std::string& scope, DiagnosticSink& sink) {
  return Converter{key, words, key_where, scope, sink}.convert();
}

std::optional<Value> default_value(const KeySchema& key) {
  if (key.default_text.empty()) return std::nullopt;
  std::vector<Word> words;
  std::size_t i = 0;
  const std::string& t = key.default_text;
  while (i < t.size()) {
    if (t[i] == ' ') {
      ++i;
      continue;
    }
    const std::size_t s = i;
    while (i < t.size() && t[i] != ' ') ++i;
    words.push_back({t.substr(s, i - s), {"<schema>", 0, 0}});
  }
  DiagnosticSink sink;
  auto v = convert_value(key, words, {"<schema>", 0, 0}, "", sink);
  sink.throw_if_any();  // a bad default is a bug in schema.cpp (caught by the schema test)
  return v;
}

std::string format_value(const KeySchema& key, const Value& value) {
  std::string s;
  auto add = [&](const std::string& w) {
    if (!s.empty()) s += ' ';
    s += w;
  };
  switch (key.kind) {
    case ValueKind::real:
    case ValueKind::reals:
    case ValueKind::quantity:
    case ValueKind::unit:
      for (double v : value.numbers) add(format_number(v));
      break;
    case ValueKind::integer:
    case ValueKind::integers:
      for (double v : value.numbers) add(std::to_string(static_cast<long long>(v)));
      break;
    case ValueKind::boolean:
      add(value.flag ? "on" : "off");
      break;
    default:
      for (const auto& w : value.words) add(w);
  }
  return s;
}

}  // namespace tribex::inputs
