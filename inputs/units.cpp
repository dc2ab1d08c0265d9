// SPDX-License-Identifier: MIT
#include "inputs/units.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace tribex::inputs {
namespace {

// "'TEXT' WHAT" built with append: GCC 12 warns (-Wrestrict, a known false positive) on
// `"'" + std::string(text) + ...` in this translation unit.
std::string quoted(std::string_view text, const char* what) {
  std::string s = "'";
  s.append(text);
  s += "' ";
  s += what;
  return s;
}

struct Symbol {
  const char* name;
  double factor;  // to SI
  Dimension dimension;
};

// Base and derived symbols. "g" is 1e-3 kg so that prefixes work as written ("ng", "kg").
constexpr Symbol symbols[] = {
    {"m", 1.0, dim::length},          {"s", 1.0, dim::time},
    {"g", 1e-3, dim::mass},           {"N", 1.0, dim::force},
    {"Pa", 1.0, dim::pressure},       {"J", 1.0, dim::energy},
    {"W", 1.0, {1, 2, -3}},           {"Hz", 1.0, dim::rate},
    {"A", 1e-10, dim::length},  // angstrom, written "A" (no prefix allowed, see below)
};

struct Prefix {
  const char* name;
  double factor;
};
constexpr Prefix prefixes[] = {{"f", 1e-15}, {"p", 1e-12}, {"n", 1e-9}, {"u", 1e-6}, {"\xC2\xB5", 1e-6},
                               {"m", 1e-3},  {"c", 1e-2},  {"k", 1e3},  {"M", 1e6},  {"G", 1e9},
                               {"T", 1e12}};

Dimension scaled(Dimension d, int p) { return {d.mass * p, d.length * p, d.time * p}; }
Dimension add(Dimension a, Dimension b) { return {a.mass + b.mass, a.length + b.length, a.time + b.time}; }

// One factor such as "nm", "m^2", "GPa", "1".
std::optional<Quantity> parse_factor(std::string_view f, std::string* error) {
  int power = 1;
  if (auto caret = f.find('^'); caret != std::string_view::npos) {
    const auto exponent = f.substr(caret + 1);
    auto [ptr, ec] = std::from_chars(exponent.data(), exponent.data() + exponent.size(), power);
    if (ec != std::errc{} || ptr != exponent.data() + exponent.size() || power == 0) {
      *error = "bad exponent in unit factor '" + std::string(f) + "'";
      return std::nullopt;
    }
    f = f.substr(0, caret);
  }
  if (f == "1") return Quantity{1.0, dim::none};
  for (const auto& s : symbols) {
    if (f == s.name) return Quantity{std::pow(s.factor, power), scaled(s.dimension, power)};
  }
  for (const auto& p : prefixes) {
    const std::string_view pn(p.name);
    if (f.size() > pn.size() && f.substr(0, pn.size()) == pn) {
      const auto rest = f.substr(pn.size());
      for (const auto& s : symbols) {
        if (rest == s.name && std::string_view(s.name) != "A")
          return Quantity{std::pow(p.factor * s.factor, power), scaled(s.dimension, power)};
      }
    }
  }
  *error = "unknown unit '" + std::string(f) + "' (known: m s g N Pa J W Hz with prefixes f p n u m c k M G T)";
  return std::nullopt;
}

}  // namespace

std::string Dimension::str() const {
  if (*this == dim::none) return "dimensionless";
  if (*this == dim::length) return "m";
  if (*this == dim::area) return "m^2";
  if (*this == dim::time) return "s";
  if (*this == dim::rate) return "1/s";
  if (*this == dim::velocity) return "m/s";
  if (*this == dim::force) return "N";
  if (*this == dim::pressure) return "Pa";
  if (*this == dim::energy) return "J";
  if (*this == dim::energy_per_area) return "J/m^2";
  if (*this == dim::density) return "kg/m^3";
  if (*this == dim::mass) return "kg";
  if (*this == dim::per_area) return "1/m^2";
  std::ostringstream s;
  s << "kg^" << mass << " m^" << length << " s^" << time;
  return s.str();
}

std::optional<Quantity> parse_unit(std::string_view unit, std::string* error) {
  Quantity result{1.0, dim::none};
  bool denominator = false;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= unit.size(); ++i) {
    const bool end = i == unit.size();
    const char c = end ? '\0' : unit[i];
    if (end || c == '*' || c == '.' || c == '/') {
      const auto factor_text = unit.substr(start, i - start);
      if (factor_text.empty()) {
        *error = "malformed unit '" + std::string(unit) + "'";
        return std::nullopt;
      }
      auto factor = parse_factor(factor_text, error);
      if (!factor) return std::nullopt;
      if (denominator) {
        result.value /= factor->value;
        result.dimension = add(result.dimension, scaled(factor->dimension, -1));
      } else {
        result.value *= factor->value;
        result.dimension = add(result.dimension, factor->dimension);
      }
      if (c == '/') {
        if (denominator) {
          *error = "at most one '/' in unit '" + std::string(unit) + "'";
          return std::nullopt;
        }
        denominator = true;
      }
      start = i + 1;
    }
  }
  return result;
}

std::optional<Quantity> parse_quantity(std::string_view text, std::string* error) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  if (text.empty()) {
    *error = "expected a number";
    return std::nullopt;
  }
  double value = 0.0;
  const char* first = text.data();
  if (*first == '+') ++first;
  auto [ptr, ec] = std::from_chars(first, text.data() + text.size(), value);
  if (ec != std::errc{} || ptr == first) {
    *error = quoted(text, "is not a number");
    return std::nullopt;
  }
  if (!std::isfinite(value)) {
    *error = quoted(text, "is not a finite number");
    return std::nullopt;
  }
  std::string_view rest(ptr, static_cast<std::size_t>(text.data() + text.size() - ptr));
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  if (rest.empty()) return Quantity{value, dim::none};
  auto unit = parse_unit(rest, error);
  if (!unit) return std::nullopt;
  const double si = value * unit->value;
  if (!std::isfinite(si)) {
    *error = quoted(text, "overflows in SI units");
    return std::nullopt;
  }
  return Quantity{si, unit->dimension};
}

}  // namespace tribex::inputs
