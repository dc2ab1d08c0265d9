// SPDX-License-Identifier: MIT
// The one command-line argument parser of the tribex subcommands.
//
//   Args a(argv_without_command, "tribex pstd", usage_text, {"--json"});
//   double f = a.real("--normal-force", 1e-6);      // optional with default
//   std::string file = a.positional(0, "FILE");      // required positional
//   a.finish();                                      // rejects unknown options, with did-you-mean
//
// Options are `--name value` or `--name=value`; flags (declared up front) are `--name`. `--help` prints the usage
// text and makes help_requested() true. Every error is a tools::BadInput (exit code 2).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "inputs/units.hpp"

namespace tribex::tools {

class Args {
 public:
  /// `flags` names the options that take no value (e.g. {"--json", "--quiet"}).
  Args(std::vector<std::string> argv, std::string command, std::string usage,
       std::set<std::string> flags = {});

  bool help_requested() const { return help_; }
  /// Prints the usage text to stdout when --help/-h was given; returns whether it was (the caller then
  /// returns exit_ok: `if (a.answered_help()) return tools::exit_ok;`).
  bool answered_help() const;
  const std::string& usage() const { return usage_; }

  bool flag(const std::string& name);
  std::optional<std::string> text(const std::string& name);
  /// Every value of an option that may be repeated (`--set A=1 --set B=2`), in command-line order.
  std::vector<std::string> texts(const std::string& name);
  std::string text(const std::string& name, const std::string& fallback);
  double real(const std::string& name, double fallback);
  std::optional<double> real(const std::string& name);
  long integer(const std::string& name, long fallback);
  /// A real with an optional unit suffix ("0.5nm", "2 um", "500nN"), returned in SI. A plain
  /// number is taken as SI; a unit of another dimension than `d` is an error.
  double quantity(const std::string& name, double fallback, inputs::Dimension d);
  std::optional<double> quantity(const std::string& name, inputs::Dimension d);
  /// Comma-separated quantities, e.g. `--window 0,0,100nm,35nm` with dimension length.
  std::vector<double> list(const std::string& name, inputs::Dimension d);

  std::string positional(std::size_t index, const std::string& what);
  std::optional<std::string> optional_positional(std::size_t index);
  std::size_t positional_count() const { return positionals_.size(); }

  /// Throws BadInput for any option that no accessor asked for.
  void finish() const;

 private:
  std::optional<std::string> take(const std::string& name, bool is_flag);
  std::string command_;
  std::string usage_;
  bool help_ = false;
  std::vector<std::string> positionals_;
  std::map<std::string, std::optional<std::string>> options_;  // value empty for bare `--x` (the last when repeated)
  std::vector<std::pair<std::string, std::optional<std::string>>> in_order_;  // every option as given
  std::set<std::string> known_;
  std::set<std::string> flags_;
};

/// Parse "VALUE[UNIT]" (see inputs/units.hpp) and check its dimension; plain numbers are SI.
/// Throws BadInput naming `what` on failure.
double parse_quantity(const std::string& text, inputs::Dimension d, const std::string& what);

}  // namespace tribex::tools
