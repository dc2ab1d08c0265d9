// SPDX-License-Identifier: MIT
// `tribex TOOL SUB ...`: the one dispatcher of the tools with subcommands (fit, friction-test, gw, surface).
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace tribex::tools {

using CommandFunction = int (*)(const std::vector<std::string>&);

struct Subcommand {
  std::string_view name;
  CommandFunction run;
};

/// Runs the subcommand args[0] with the arguments after it. `--help`/`-h`: prints `usage` to stdout,
/// exit 0. No subcommand, or one not in `table`: BadInput naming `command` (e.g. "tribex gw"), the
/// choices and the closest one (exit 2).
int run_subcommand(const std::vector<std::string>& args, std::string_view command, const char* usage,
                   std::initializer_list<Subcommand> table);

}  // namespace tribex::tools
