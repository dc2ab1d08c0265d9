// SPDX-License-Identifier: MIT
#include "tools/common/subcommands.hpp"

#include <cstdio>

#include "inputs/did_you_mean.hpp"
#include "tools/common/errors.hpp"

namespace tribex::tools {

int run_subcommand(const std::vector<std::string>& args, std::string_view command, const char* usage,
                   std::initializer_list<Subcommand> table) {
  std::vector<std::string> names;
  std::string choices;
  for (const Subcommand& s : table) {
    choices += (names.empty() ? "" : names.size() + 1 == table.size() ? " or " : ", ") + std::string(s.name);
    names.emplace_back(s.name);
  }
  const std::string cmd(command);
  if (args.empty()) throw BadInput(cmd + " needs a subcommand: " + choices + " (see " + cmd + " --help)");
  if (args[0] == "--help" || args[0] == "-h") {
    std::fputs(usage, stdout);
    return exit_ok;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  for (const Subcommand& s : table)
    if (args[0] == s.name) return s.run(rest);
  const std::string hint = inputs::closest_match(args[0], names);
  throw BadInput(cmd + ": unknown subcommand '" + args[0] + "' (use " + choices +
                 (hint.empty() ? ";" : "; did you mean '" + hint + "'?") + " see --help)");
}

}  // namespace tribex::tools
