// SPDX-License-Identifier: MIT
// Recursive descent over the grammar (lowest precedence first):
//   sum     = product { ("+" | "-") product }
//   product = unary { ("*" | "/") unary }
//   unary   = ("-" | "+") unary | power
//   power   = primary [ "^" unary ]          (right-associative: 2^3^2 = 2^9; -2^2 = -4)
//   primary = NUMBER [UNIT] | NAME | "(" sum ")"
#include "inputs/expression.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "inputs/values.hpp"

namespace tribex::inputs {
namespace {

struct Failure {
  std::string message;
};

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
// Characters a unit may hold ("J/m^2", "kg*m^-1", "µm": the UTF-8 bytes of µ are >= 0x80).
bool unit_char(char c) {
  return is_letter(c) || is_digit(c) || c == '^' || c == '/' || c == '*' || c == '.' || c == '-' ||
         static_cast<unsigned char>(c) >= 0x80;
}

Dimension combine(Dimension a, Dimension b, int sign) {
  return {a.mass + sign * b.mass, a.length + sign * b.length, a.time + sign * b.time};
}

class Parser {
 public:
  Parser(std::string_view text, const NameLookup& lookup) : t_(text), lookup_(lookup) {}

  Quantity parse() {
    Quantity q = sum();
    skip();
    if (i_ < t_.size()) fail("unexpected '" + std::string(1, t_[i_]) + "'" + where() + "; expected an operator + - * / ^");
    if (!std::isfinite(q.value)) fail("the value is not finite (overflow or division by zero)");
    return q;
  }

 private:
  [[noreturn]] void fail(const std::string& m) const { throw Failure{m}; }
  std::string where() const { return " at character " + std::to_string(i_ + 1); }
  void skip() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t')) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < t_.size() && t_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }

  Quantity sum() {
    Quantity a = product();
    for (;;) {
      const bool plus = eat('+');
      if (!plus && !eat('-')) return a;
      const Quantity b = product();
      if (!(a.dimension == b.dimension))
        fail("cannot " + std::string(plus ? "add " : "subtract ") + describe_dimension(b.dimension) +
             (plus ? " to " : " from ") + describe_dimension(a.dimension) + "; give both terms the same unit");
      a.value = plus ? a.value + b.value : a.value - b.value;
    }
  }

  Quantity product() {
    Quantity a = unary();
    for (;;) {
      const bool times = eat('*');
      if (!times && !eat('/')) return a;
      const Quantity b = unary();
      a.value = times ? a.value * b.value : a.value / b.value;
      a.dimension = combine(a.dimension, b.dimension, times ? 1 : -1);
    }
  }

  Quantity unary() {
    if (eat('-')) {
      Quantity q = unary();
      q.value = -q.value;
      return q;
    }
    if (eat('+')) return unary();
    return power();
  }

  Quantity power() {
    Quantity base = primary();
    if (!eat('^')) return base;
    const Quantity e = unary();
    if (!(e.dimension == dim::none)) fail("an exponent must be dimensionless, got " + describe_dimension(e.dimension));
    Quantity r{std::pow(base.value, e.value), dim::none};
    if (!(base.dimension == dim::none)) {
      // A unit's exponents stay integers: (m^2/s^2)^(1/2) = m/s is fine, m^(1/2) is not.
      int out[3] = {};
      const int in[3] = {base.dimension.mass, base.dimension.length, base.dimension.time};
      for (int k = 0; k < 3; ++k) {
        const double x = in[k] * e.value, n = std::round(x);
        if (std::fabs(x - n) > 1e-9 || std::fabs(n) > 12)
          fail("(" + describe_dimension(base.dimension) + ")^" + std::to_string(e.value) +
               " has no unit with integer powers (up to 12); make the base dimensionless first (divide by its unit)");
        out[k] = static_cast<int>(n);
      }
      r.dimension = {out[0], out[1], out[2]};
    }
    return r;
  }

  Quantity primary() {
    skip();
    if (i_ >= t_.size()) fail("the expression ends where a number, a name or '(' is expected");
    const char c = t_[i_];
    if (c == '(') {
      ++i_;
      Quantity q = sum();
      if (!eat(')')) fail("missing ')'" + where());
      return q;
    }
    if (is_digit(c) || c == '.') return number();
    if (is_letter(c)) {
      const std::size_t start = i_;
      while (i_ < t_.size() && (is_letter(t_[i_]) || is_digit(t_[i_]))) ++i_;
      const std::string_view name = t_.substr(start, i_ - start);
      const Quantity* q = lookup_(name);
      if (!q) fail("'" + std::string(name) + "' is not defined; define it above on a line of its own, {" +
                   std::string(name) + " = VALUE}");
      return *q;
    }
    fail("unexpected '" + std::string(1, c) + "'" + where() + "; expected a number, a name or '('");
  }

  // A number, then (after blanks) the longest run of unit characters that reads as a unit.
  Quantity number() {
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(t_.data() + i_, t_.data() + t_.size(), v);
    if (ec != std::errc{}) fail("'" + std::string(t_.substr(i_)) + "' is not a number");
    i_ = static_cast<std::size_t>(ptr - t_.data());
    Quantity q{v, dim::none};
    std::size_t j = i_;
    while (j < t_.size() && (t_[j] == ' ' || t_[j] == '\t')) ++j;
    if (j >= t_.size() || !(is_letter(t_[j]) || static_cast<unsigned char>(t_[j]) >= 0x80)) return q;
    std::size_t end = j;
    while (end < t_.size() && unit_char(t_[end])) ++end;
    for (std::size_t e = end; e > j; --e) {
      std::string ignored;
      if (const auto u = parse_unit(t_.substr(j, e - j), &ignored)) {
        i_ = e;
        return {v * u->value, u->dimension};
      }
    }
    std::string error;
    parse_unit(t_.substr(j, end - j), &error);
    fail(error + " after a number (a unit comes right after its number; a parameter's name after an operator: 2*W)");
  }

  std::string_view t_;
  const NameLookup& lookup_;
  std::size_t i_ = 0;
};

}  // namespace

std::optional<Quantity> evaluate_expression(std::string_view text, const NameLookup& lookup, std::string* error) {
  try {
    return Parser(text, lookup).parse();
  } catch (const Failure& f) {
    *error = f.message;
    return std::nullopt;
  }
}

std::string si_unit_text(const Dimension& d) {
  if (d == dim::none) return "";
  const std::string named = d.str();
  if (named.find(' ') == std::string::npos) return named;  // "m", "J/m^2", "kg/m^3", ...
  std::string s;
  const auto add = [&](const char* symbol, int p) {
    if (p == 0) return;
    if (!s.empty()) s += '*';
    s += symbol;
    if (p != 1) {
      s += '^';
      s += std::to_string(p);
    }
  };
  add("kg", d.mass);
  add("m", d.length);
  add("s", d.time);
  return s;
}

bool is_parameter_name(std::string_view name) {
  if (name.empty() || !is_letter(name.front())) return false;
  for (char c : name)
    if (!is_letter(c) && !is_digit(c)) return false;
  return true;
}

}  // namespace tribex::inputs
