// SPDX-License-Identifier: MIT
// `tribex plot history OUT [PNG] [--columns a,b] [--title T]`: the standard history panels of a run
// (force, energy, contact radius; tools/plot/plot_history.py, drawn by Debian's /usr/bin/python3 with
// matplotlib). The arguments are checked here; the script's own exit code is returned (2: bad input).
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tools/cli/commands.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"
#include "tools/common/panel_plot.hpp"

#ifndef TRIBEX_PLOT_HISTORY_SCRIPT
#define TRIBEX_PLOT_HISTORY_SCRIPT "tools/plot/plot_history.py"
#endif

namespace tribex::cli {
namespace {

const char* plot_usage =
    "usage: tribex plot history OUT [PNG] [--columns a,b,c] [--title T]\n"
    "  The standard history panels of a run, each with its unit and a legend: contact forces (nN),\n"
    "  energies with the energy error, contact radius and its estimators (nm); panels of all-zero\n"
    "  columns are left out. OUT: a run's output folder (or its history.csv); PNG: default\n"
    "  OUT/history.png. --columns: those history.csv columns on one axis instead.\n"
    "  Needs /usr/bin/python3 with matplotlib (python3-matplotlib). Same as\n"
    "  /usr/bin/python3 tools/plot/plot_history.py OUT [PNG] [--columns ...].\n";

}  // namespace

int plot_command(const std::vector<std::string>& argv) {
  tools::Args a(argv, "tribex plot", plot_usage);
  if (a.answered_help()) return tools::exit_ok;
  const std::string what = a.positional(0, "history");
  if (what != "history")
    throw tools::BadInput("tribex plot: unknown plot '" + what + "'; the one plot is 'history' (tribex plot history OUT)");
  const std::string out = a.positional(1, "OUT");
  const auto png = a.optional_positional(2);
  const auto columns = a.text("--columns");
  const auto title = a.text("--title");
  a.finish();
  if (a.positional_count() > 3)
    throw tools::BadInput("tribex plot history: unexpected argument '" + *a.optional_positional(3) +
                          "' (OUT and an optional PNG; options start with --)");
  namespace fs = std::filesystem;
  const fs::path history = fs::is_directory(out) ? fs::path(out) / "history.csv" : fs::path(out);
  if (!fs::is_regular_file(history))
    throw tools::BadInput("tribex plot history: " + history.string() +
                          ": no such file; give the output folder of a tribex run (-o OUT) or its history.csv");
  // Built with append: GCC 12 warns (-Wrestrict, a known false positive) on `" " + std::string`.
  std::vector<std::string> parts = {TRIBEX_PLOT_HISTORY_SCRIPT, out};
  if (png) parts.push_back(*png);
  for (const auto& [option, value] : {std::pair{"--columns", columns}, std::pair{"--title", title}})
    if (value) {
      parts.emplace_back(option);
      parts.push_back(*value);
    }
  std::string cmd = "/usr/bin/python3";
  for (const auto& part : parts) {
    cmd += ' ';
    cmd += tools::shell_quote(part);
  }
  const int rc = std::system(cmd.c_str());
  if (rc == -1 || !WIFEXITED(rc)) return 1;
  return WEXITSTATUS(rc);
}

}  // namespace tribex::cli
