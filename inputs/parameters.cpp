// SPDX-License-Identifier: MIT
#include "inputs/parameters.hpp"

#include <charconv>
#include <cmath>

#include "inputs/expression.hpp"
#include "inputs/values.hpp"

namespace tribex::inputs {
namespace {

std::string shortest(double v) {
  char b[40];  // shortest text that reads back as the same double
  const auto r = std::to_chars(b, b + sizeof b, v);
  return std::string(b, r.ptr);
}

std::string trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return std::string(s);
}

std::string joined(const LogicalLine& line) {
  std::string s;
  for (const Word& w : line.words) s += (s.empty() ? "" : " ") + w.text;
  return s;
}

std::string value_text(const Quantity& q) { return shortest(q.value) + si_unit_text(q.dimension); }

struct Expander {
  const std::vector<ParameterSetting>& settings;
  const std::string& deck_file;
  std::vector<DeckParameter>& parameters;
  DiagnosticSink& sink;
  std::vector<Quantity> values;  // parallel to `parameters`
  std::vector<std::string> failed;  // definitions with an error (reported once: their uses stay quiet)
  bool touched_failed = false;      // the last evaluation used one of them
  Quantity poison{NAN, dim::none};

  const Quantity* lookup(std::string_view name) {
    for (std::size_t i = 0; i < parameters.size(); ++i)
      if (parameters[i].name == name) return &values[i];
    for (const std::string& f : failed)
      if (f == name) {
        touched_failed = true;
        return &poison;
      }
    return nullptr;
  }
  std::optional<Quantity> evaluate(const std::string& text, std::string* error) {
    touched_failed = false;
    return evaluate_expression(text, [this](std::string_view n) { return lookup(n); }, error);
  }
  // A problem, unless it follows from an earlier definition's (already reported).
  void report(const SourceLocation& where, const std::string& message) {
    if (!touched_failed) sink.error(where, "", message);
  }

  // `{NAME = EXPRESSION}` alone on its line.
  void define(const LogicalLine& line, const std::string& text) {
    const std::string inner = text.substr(1, text.size() - 2);
    const auto eq = inner.find('=');
    const std::string name = trim(inner.substr(0, eq)), expression = trim(inner.substr(eq + 1));
    if (!is_parameter_name(name))
      return sink.error(line.where(), "", "'" + text + "': '" + name + "' is not a parameter name; a name is a letter or _ "
                                          "then letters, digits, _ (e.g. {W = 0.05 J/m^2})");
    for (const DeckParameter& p : parameters)
      if (p.name == name)
        return sink.error(line.where(), "", "parameter '" + name + "' is already defined at " + p.where.str() +
                                                "; define it once (change the value there, or vary it with --set " +
                                                name + "=VALUE)");
    std::string error;
    auto q = evaluate(expression, &error);
    if (!q) {
      report(line.where(), "'" + text + "': " + error);
      return failed.push_back(name);
    }
    DeckParameter p{name, 0.0, "", false, line.where()};
    for (const ParameterSetting& s : settings) {
      if (s.name != name) continue;
      const std::string arg = "--set " + s.name + "=" + s.expression;
      auto set = evaluate(s.expression, &error);
      if (!set) {
        report(line.where(), arg + ": " + error);
        return failed.push_back(name);
      }
      if (set->dimension == dim::none) set->dimension = q->dimension;  // plain numbers are SI of the definition
      if (!(set->dimension == q->dimension)) {
        sink.error(line.where(), "", arg + ": '" + name + "' is " + describe_dimension(q->dimension) +
                                         " here, got " + describe_dimension(set->dimension) +
                                         "; give a plain SI number or a unit of its dimension");
        return failed.push_back(name);
      }
      q = set;
      p.set_on_command_line = true;
    }
    p.value = q->value;
    p.unit = si_unit_text(q->dimension);
    parameters.push_back(p);
    values.push_back(*q);
  }

  // Every `{EXPRESSION}` of a line replaced by its value; words re-split at blanks (a value keeps
  // the location of the word its `{` was in).
  LogicalLine substitute(const LogicalLine& line) {
    std::string text;
    std::vector<std::size_t> owner;  // word of each character of `text`
    for (std::size_t i = 0; i < line.words.size(); ++i) {
      if (i > 0) text += ' ', owner.push_back(i);
      text += line.words[i].text;
      owner.resize(text.size(), i);
    }
    LogicalLine out;
    std::string current;
    SourceLocation current_where;
    const auto flush = [&] {
      if (!current.empty()) out.words.push_back({current, current_where});
      current.clear();
    };
    const auto start = [&](std::size_t pos) {
      if (current.empty()) current_where = line.words[owner[pos]].where;
    };
    for (std::size_t pos = 0; pos < text.size();) {
      const char c = text[pos];
      const SourceLocation& here = line.words[owner[pos]].where;
      if (c == ' ') {
        flush();
        ++pos;
      } else if (c == '}') {
        sink.error(here, "", "'}' without its '{'; write {EXPRESSION} or remove the '}'");
        ++pos;
      } else if (c != '{') {
        start(pos);
        current += c;
        ++pos;
      } else {
        const auto close = text.find('}', pos);
        if (close == std::string::npos) {
          sink.error(here, "", "'{' without its '}' on this line; close the expression: {EXPRESSION}");
          break;
        }
        const std::string inner = text.substr(pos + 1, close - pos - 1);
        std::string error;
        if (inner.find('{') != std::string::npos) {
          sink.error(here, "", "'{' inside '{...}'; expressions do not nest (use parentheses)");
        } else if (inner.find('=') != std::string::npos) {
          sink.error(here, "", "'{" + inner + "}': a definition {NAME = VALUE} must be a line of its own");
        } else if (const auto q = evaluate(inner, &error)) {
          start(pos);
          current += value_text(*q);
        } else {
          report(here, "'{" + inner + "}': " + error);
        }
        pos = close + 1;
      }
    }
    flush();
    return out;
  }
};

}  // namespace

std::optional<ParameterSetting> parse_parameter_setting(const std::string& text, std::string* error) {
  const auto eq = text.find('=');
  const std::string name = trim(text.substr(0, eq));
  if (eq == std::string::npos || !is_parameter_name(name) || trim(text.substr(eq + 1)).empty()) {
    *error = "--set expects NAME=VALUE (e.g. --set W=0.06 or --set \"R=20 nm\"), got '" + text + "'";
    return std::nullopt;
  }
  return ParameterSetting{name, trim(text.substr(eq + 1))};
}

std::vector<LogicalLine> expand_parameters(const std::vector<LogicalLine>& lines,
                                           const std::vector<ParameterSetting>& settings,
                                           const std::string& deck_file, std::vector<DeckParameter>& parameters,
                                           DiagnosticSink& sink) {
  Expander ex{settings, deck_file, parameters, sink, {}, {}, false, {NAN, dim::none}};
  for (std::size_t i = 0; i < settings.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (settings[i].name == settings[j].name)
        sink.error({deck_file, 0, 0}, "", "--set " + settings[i].name + " is given twice; give each parameter once");
  std::vector<LogicalLine> out;
  for (const LogicalLine& line : lines) {
    const std::string text = joined(line);
    const bool braces = text.find_first_of("{}") != std::string::npos;
    if (!braces) {
      out.push_back(line);
      continue;
    }
    const bool definition = text.size() > 2 && text.front() == '{' && text.back() == '}' &&
                            text.find('{', 1) == std::string::npos && text.find('}') == text.size() - 1 &&
                            text.find('=') != std::string::npos;
    if (definition) {
      ex.define(line, text);
    } else if (LogicalLine expanded = ex.substitute(line); !expanded.words.empty()) {
      out.push_back(std::move(expanded));
    }
  }
  for (const ParameterSetting& s : settings) {
    if (ex.lookup(s.name)) continue;  // defined (or failed: reported at its line)
    std::string names;
    for (const DeckParameter& p : parameters) names += (names.empty() ? "" : ", ") + p.name;
    sink.error({deck_file, 0, 0}, "",
               "--set " + s.name + "=" + s.expression + ": the deck defines no parameter '" + s.name + "'; " +
                   (names.empty() ? std::string("it defines none (define one with a line {NAME = VALUE})")
                                  : "it defines: " + names));
  }
  return out;
}

std::string parameter_definitions_text(const std::vector<DeckParameter>& parameters) {
  std::string s = parameters.empty() ? "" : "# parameters in SI, --set values applied\n";
  for (const DeckParameter& p : parameters)
    s += "{" + p.name + " = " + shortest(p.value) + (p.unit.empty() ? "" : " " + p.unit) + "}\n";
  return s;
}

}  // namespace tribex::inputs
