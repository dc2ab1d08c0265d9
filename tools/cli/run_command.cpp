// SPDX-License-Identifier: MIT
// `tribex run DECK [-o OUTDIR] [--quiet]` and `tribex check DECK`.
#include <cstdlib>
#include <filesystem>

#include "inputs/diagnostics.hpp"
#include "inputs/parameters.hpp"
#include "inputs/result_fields.hpp"
#include "solver/output/rigid_body_history.hpp"
#include "solver/output/history_columns.hpp"
#include "solver/output/output_tables.hpp"
#include "solver/run/run.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/rank_launcher.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"

namespace tribex::cli {
namespace {

const char* run_usage =
    "tribex run DECK [-o OUTDIR] [--quiet] [--restart FILE [--restart-allow-changed]] [--stop-at-step N]\n"
    "           [--heartbeat SECONDS] [--set NAME=VALUE ...] [--ranks N]\n"
    "tribex run --list-columns | --list-summary-keys | --list-fields\n"
    "  Runs an input deck. Outputs go to OUTDIR (default ./<deck name>_output): history.csv,\n"
    "  results.h5 + results.xdmf (open the .xdmf in ParaView), summary.json, log.txt.\n"
    "  --quiet   no progress line and no terminal echo (log.txt is still written)\n"
    "  --restart FILE   resume from a restart file (OUT/restart.h5 = the newest) written by the same\n"
    "            deck with 'begin restart output'; same number of MPI ranks; outputs continue in OUTDIR.\n"
    "            A restart file written by another deck or mesh is refused (exit 2, naming the difference)\n"
    "  --restart-allow-changed   resume although the deck differs (e.g. a longer termination time)\n"
    "  --stop-at-step N stop after step N as if interrupted (exit 130; writes a restart file)\n"
    "  --heartbeat SECONDS  when stdout is not a terminal (batch job, pipe, file): a progress line\n"
    "            (step, time, percent, ETA, dt, energy error) to stdout and log.txt this often\n"
    "            (wall time, default 60; 0: none; with --quiet to log.txt only)\n"
    "  --set NAME=VALUE replace the value of the deck's parameter {NAME = ...} (repeatable; VALUE an\n"
    "            expression with units, a plain number is SI: --set W=0.06, --set \"R=20 nm\"; inputs/README.md)\n"
    "  --ranks N   run on N MPI ranks: starts mpirun -np N and stays its parent; a SIGINT/SIGTERM to this\n"
    "            command stops the ranks cleanly (outputs valid, restart file) and it exits 130. Same as\n"
    "            mpirun -np N tribex run ..., whose own exit code after SIGTERM is Open MPI's 1\n"
    "  --list-columns   print every column history.csv can have, with its unit and definition\n"
    "            (history_columns.csv beside each history.csv lists a run's own), and exit\n"
    "  --list-summary-keys   print every key of summary.json (energies.NAME, warnings[].NAME,\n"
    "            rank_counts[].NAME for the fields of those) with its unit and definition, and exit\n"
    "  --list-fields   print every result field ('nodal variables', 'element variables' of 'begin results\n"
    "            output'): name, kind, SI unit and definition, and exit\n"
    "  Exit codes: 0 ok, 2 bad input, 3 numerical failure, 130 interrupted (outputs valid).\n";

const char* check_usage =
    "tribex check DECK [--set NAME=VALUE ...]\n"
    "  Validates a deck and its mesh without running: prints the blocks, element and node counts,\n"
    "  materials, the deck's parameters, the stable time step and the element that controls it.\n"
    "  Writes nothing. --set as for tribex run (a deck check accepts with them, run sets up).\n";

// A second positional argument is refused, not ignored (one deck per run or check).
void one_deck(tools::Args& args, const char* command) {
  if (args.positional_count() > 1)
    throw tools::BadInput(std::string(command) + ": unexpected argument '" + *args.optional_positional(1) +
                          "' (one DECK; options start with --)");
}

// One line per row of a summary.json table: key (under `prefix`), unit ("" for text), definition.
template <class T>
void print_fields(const std::string& prefix, std::span<const solver::Field<T>> table) {
  for (const auto& f : table)
    std::printf("%-36s %-7s %s\n", (prefix + std::string(f.name)).c_str(), std::string(f.unit).c_str(),
                std::string(f.definition).c_str());
}

// Every `--set NAME=VALUE`, in order.
std::vector<inputs::ParameterSetting> parameter_settings(tools::Args& args, const char* command) {
  std::vector<inputs::ParameterSetting> out;
  for (const std::string& text : args.texts("--set")) {
    std::string error;
    const auto s = inputs::parse_parameter_setting(text, &error);
    if (!s) throw tools::BadInput(std::string(command) + ": " + error);
    out.push_back(*s);
  }
  return out;
}

bool args_has_stop(const std::vector<std::string>& argv) {
  for (const auto& a : argv)
    if (a == "--stop-at-step" || a.rfind("--stop-at-step=", 0) == 0) return true;
  return false;
}

}  // namespace

int run_command(const std::vector<std::string>& argv) {
  tools::Args args(argv, "tribex run", run_usage, {"--quiet", "--restart-allow-changed", "--list-columns",
                                                             "--list-summary-keys", "--list-fields"});
  if (args.answered_help()) return tools::exit_ok;
  if (args.flag("--list-columns")) {
    args.finish();
    auto columns = solver::describe_history_columns(true, {"SET"}, {"SET"}, true);
    for (const auto& c : solver::describe_rigid_body_columns({"BODY"}, true)) columns.push_back(c);
    for (const auto& c : columns)
      std::printf("%-28s %-7s %s\n", c.name.c_str(), c.unit.c_str(), c.definition.c_str());
    return 0;
  }
  if (args.flag("--list-fields")) {
    args.finish();
    std::printf("%-26s %-8s %-10s %s\n", "name", "kind", "unit", "definition");
    inputs::for_each_result_field([](const auto& f) {
      std::printf("%-26s %-8s %-10s %s\n", std::string(f.name).c_str(),
                  f.kind == inputs::FieldKind::nodal ? "nodal" : "element", std::string(f.unit).c_str(),
                  std::string(f.definition).c_str());
    });
    return 0;
  }
  if (args.flag("--list-summary-keys")) {
    args.finish();
    print_fields("", solver::summary_fields());
    print_fields("energies.", solver::energy_fields());
    print_fields("warnings[].", solver::warning_fields());
    print_fields("rank_counts[].", solver::rank_count_fields());
    return 0;
  }
  const std::string deck_path = args.positional(0, "DECK");
  const bool quiet = args.flag("--quiet");
  auto out = args.text("-o");
  if (!out) out = args.text("--output");
  const auto restart = args.text("--restart");
  const bool allow_changed = args.flag("--restart-allow-changed");
  const long stop_at = args.integer("--stop-at-step", -1);
  const double heartbeat = args.real("--heartbeat", 60.0);
  const auto settings = parameter_settings(args, "tribex run");
  const long ranks = args.integer("--ranks", 1);
  args.finish();
  one_deck(args, "tribex run");
  if (ranks < 1 || ranks > 1'000'000)
    throw tools::BadInput("tribex run: option --ranks expects a number of MPI ranks in [1, 1000000], got " +
                          std::to_string(ranks));
  if (ranks > 1 && std::getenv("OMPI_COMM_WORLD_SIZE"))
    throw tools::BadInput("tribex run: --ranks starts mpirun itself; under mpirun give the rank count to mpirun "
                          "(-np N) and leave --ranks out");
  if (stop_at < 0 && args_has_stop(argv))
    throw tools::BadInput("tribex run: option --stop-at-step expects a step number >= 0, got " + std::to_string(stop_at));
  if (!(heartbeat >= 0.0))
    throw tools::BadInput("tribex run: option --heartbeat expects a number of seconds >= 0 (0 turns the heartbeat off)");
  const inputs::Deck deck = inputs::parse_deck_file(deck_path, settings);
  if (ranks > 1) return run_under_mpirun(static_cast<int>(ranks), without_ranks_option(argv));
  solver::RunOptions options;
  options.quiet = quiet;
  if (restart) options.restart_path = *restart;
  options.restart_allow_changed = allow_changed;
  options.stop_at_step = stop_at;
  options.heartbeat_seconds = heartbeat;
  options.output_directory = out ? *out : std::filesystem::path(deck_path).stem().string() + "_output";
  return solver::run_deck(deck, options).exit_code;
}

int check_command(const std::vector<std::string>& argv) {
  tools::Args args(argv, "tribex check", check_usage);
  if (args.answered_help()) return tools::exit_ok;
  const std::string deck_path = args.positional(0, "DECK");
  const auto settings = parameter_settings(args, "tribex check");
  args.finish();
  one_deck(args, "tribex check");
  const inputs::Deck deck = inputs::parse_deck_file(deck_path, settings);
  std::printf("deck %s: %zu material(s), %zu section(s), %zu function(s)\n", deck_path.c_str(),
              deck.materials.size(), deck.sections.size(), deck.functions.size());
  for (const auto& m : deck.materials)
    for (const auto& p : m.models)
      std::printf("  material %-12s %-11s rho %.6g kg/m^3, E %.6g Pa, nu %.4g\n", m.name.c_str(),
                  p.model.c_str(), m.density, p.youngs_modulus,
                  p.poissons_ratio);
  solver::RunOptions options;
  options.check_only = true;
  solver::run_deck(deck, options);
  std::printf("deck OK\n");
  return 0;
}

}  // namespace tribex::cli
