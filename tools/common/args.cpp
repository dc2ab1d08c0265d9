// SPDX-License-Identifier: MIT
#include "tools/common/args.hpp"

#include <charconv>
#include <cstdio>
#include <sstream>

#include "inputs/did_you_mean.hpp"
#include "tools/common/errors.hpp"

namespace tribex::tools {

Args::Args(std::vector<std::string> argv, std::string command, std::string usage,
           std::set<std::string> flags)
    : command_(std::move(command)), usage_(std::move(usage)), flags_(std::move(flags)) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a == "--help" || a == "-h") {
      help_ = true;
    } else if (a.rfind("--", 0) == 0 && a.size() > 2) {
      const auto eq = a.find('=');
      if (eq != std::string::npos) {
        options_[a.substr(0, eq)] = a.substr(eq + 1);
      } else if (!flags_.count(a) && i + 1 < argv.size()) {
        options_[a] = argv[i + 1];
        ++i;
      } else {
        options_[a] = std::nullopt;
      }
      in_order_.emplace_back(eq != std::string::npos ? a.substr(0, eq) : a, options_[eq != std::string::npos ? a.substr(0, eq) : a]);
    } else if (a == "-o") {  // a trailing -o with no folder is an error of take(), not a positional
      options_["-o"] = i + 1 < argv.size() ? std::optional<std::string>(argv[++i]) : std::nullopt;
    } else {
      positionals_.push_back(a);
    }
  }
}

bool Args::answered_help() const {
  if (help_) std::fputs(usage_.c_str(), stdout);
  return help_;
}

std::optional<std::string> Args::take(const std::string& name, bool is_flag) {
  known_.insert(name);
  auto it = options_.find(name);
  if (it == options_.end()) return std::nullopt;
  if (is_flag && it->second) throw BadInput(command_ + ": option " + name + " takes no value");
  if (!is_flag && !it->second) throw BadInput(command_ + ": option " + name + " needs a value (see --help)");
  return is_flag ? std::optional<std::string>("") : it->second;
}

bool Args::flag(const std::string& name) { return take(name, true).has_value(); }

std::optional<std::string> Args::text(const std::string& name) { return take(name, false); }

std::vector<std::string> Args::texts(const std::string& name) {
  std::vector<std::string> out;
  if (!take(name, false)) return out;  // also: a bare `--x` with no value is refused
  for (const auto& [option, value] : in_order_) {
    if (option != name) continue;
    if (!value) throw BadInput(command_ + ": option " + name + " needs a value (see --help)");
    out.push_back(*value);
  }
  return out;
}

std::string Args::text(const std::string& name, const std::string& fallback) {
  auto v = take(name, false);
  return v ? *v : fallback;
}

std::optional<double> Args::real(const std::string& name) {
  auto v = take(name, false);
  if (!v) return std::nullopt;
  return parse_quantity(*v, inputs::dim::none, command_ + " " + name);
}

double Args::real(const std::string& name, double fallback) {
  auto v = real(name);
  return v ? *v : fallback;
}

long Args::integer(const std::string& name, long fallback) {
  auto v = take(name, false);
  if (!v) return fallback;
  long out = 0;
  auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
  if (ec != std::errc{} || ptr != v->data() + v->size())
    throw BadInput(command_ + ": option " + name + " expects an integer, got '" + *v + "'");
  return out;
}

std::optional<double> Args::quantity(const std::string& name, inputs::Dimension d) {
  auto v = take(name, false);
  if (!v) return std::nullopt;
  return parse_quantity(*v, d, command_ + " " + name);
}

double Args::quantity(const std::string& name, double fallback, inputs::Dimension d) {
  auto v = quantity(name, d);
  return v ? *v : fallback;
}

std::vector<double> Args::list(const std::string& name, inputs::Dimension d) {
  std::vector<double> out;
  auto v = take(name, false);
  if (!v) return out;
  std::stringstream ss(*v);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(parse_quantity(item, d, command_ + " " + name));
  return out;
}

std::string Args::positional(std::size_t index, const std::string& what) {
  auto v = optional_positional(index);
  if (!v) throw BadInput(command_ + ": missing " + what + " (usage: " + usage_.substr(0, usage_.find('\n')) + ")");
  return *v;
}

std::optional<std::string> Args::optional_positional(std::size_t index) {
  if (index >= positionals_.size()) return std::nullopt;
  return positionals_[index];
}

void Args::finish() const {
  std::vector<std::string> known(known_.begin(), known_.end());
  for (const auto& [name, value] : options_) {
    if (known_.count(name)) continue;
    std::string hint = inputs::closest_match(name, known);
    throw BadInput(command_ + ": unknown option " + name +
                   (hint.empty() ? " (see --help)" : " (did you mean " + hint + "?)"));
  }
}

double parse_quantity(const std::string& text, inputs::Dimension d, const std::string& what) {
  std::string error;
  auto q = inputs::parse_quantity(text, &error);
  if (!q) throw BadInput(what + ": " + error);
  if (q->dimension != d && q->dimension != inputs::dim::none)
    throw BadInput(what + ": '" + text + "' has units of " + q->dimension.str() + ", expected " + d.str());
  return q->value;
}

}  // namespace tribex::tools
