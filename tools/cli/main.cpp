// SPDX-License-Identifier: MIT
// The `tribex` front end: dispatches to subcommands and maps every error type of the layers
// below onto the exit codes of docs/architecture.md (0 ok, 1 internal, 2 bad input, 3 numerical
// failure, 130 interrupted). A new subcommand is one row in `commands` below plus its function
// `int NAME_command(const std::vector<std::string>& args)` declared in tools/cli/commands.hpp.
#include <mpi.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "inputs/did_you_mean.hpp"
#include "tools/cli/commands.hpp"
#include "solver/run/stop_signal.hpp"
#include "tools/cli/error_mapping.hpp"

namespace {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const std::vector<std::string>&);
};

const std::vector<Command> commands = {
    {"run", "run an input deck: tribex run DECK [-o OUTDIR] [--quiet]", tribex::cli::run_command},
    {"check", "validate a deck and its mesh, print the set-up summary, run nothing", tribex::cli::check_command},
    {"keys", "the deck key reference from the schema: tribex keys [BLOCK] [--markdown]", tribex::cli::keys_command},
    {"plot", "pictures of a run: tribex plot history OUT (force, energy, contact radius panels)", tribex::cli::plot_command},
    {"bench", "benchmarks: tribex bench block --n N --element E --material M --steps S", tribex::cli::bench_command},
    {"gw", "Greenwood-Williamson models: F_n, discrete/DMT/tangential GW (CSV)", tribex::cli::gw_command},
    {"surface", "rough-surface statistics of AFM maps and McCool GW tables", tribex::cli::surface_command},
    {"pstd", "pre-sliding tangential deflection model (report 2.1.9)", tribex::cli::pstd_command},
    {"friction-test", "friction-test data reduction: spring calibration, mu_s, mu_d", tribex::cli::friction_test_command},
    {"fit", "fit tau* and W to AFM friction-vs-load data (report Eq. 3.1, DMT/JKR/COS/MD)", tribex::cli::fit_command},
    {"layered", "sphere on bonded elastic layers: a, delta, f against P~ and A, b (continuum reference)", tribex::cli::layered_command},
    {"adhesion-curve", "Lennard-Jones sphere on a flat: load-approach curve, pull-off, jump-in/out (reference)", tribex::cli::adhesion_curve_command},
    {"mesh", "mesh generators (.msh): tribex mesh afm FILE --window ... -o MESH.msh", tribex::cli::mesh_command},
    {"join", "a parallel run's per-rank results.exo.N.r joined into OUT/results.exo: tribex join OUT", tribex::cli::join_command},
};

void print_usage(std::FILE* to) {
  std::fprintf(to, "usage: tribex COMMAND [ARGS...]   (tribex COMMAND --help for details)\n\ncommands:\n");
  for (const auto& c : commands) std::fprintf(to, "  %-14s %s\n", c.name, c.summary);
}

// `run` is an MPI program (a run without mpirun is one rank). Every rank runs the
// command with its error messages into a buffer; afterwards the ranks agree: the lowest rank that
// printed an error prints it (once), and every rank exits with that rank's code.
// Without a launcher (no mpirun/mpiexec environment) MPI is not started at all: Open MPI's
// singleton start costs about 0.5 s per process, and the run is the one-rank case anyway (the
// helpers of solver/parallel/communicator.hpp treat an uninitialised MPI as one rank).
bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

int run_parallel(int argc, char** argv, const Command& c, const std::vector<std::string>& args) {
  if (!launched_by_mpirun()) return tribex::cli::run_mapping_errors([&] { return c.run(args); });
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  char* text = nullptr;
  std::size_t length = 0;
  std::FILE* err = size > 1 ? open_memstream(&text, &length) : stderr;
  int code = tribex::cli::run_mapping_errors([&] { return c.run(args); }, err);
  if (size > 1) {
    std::fclose(err);
    const bool has_message = code != 0 && length > 0;
    int first = has_message ? rank : INT_MAX;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first != INT_MAX) {
      MPI_Bcast(&code, 1, MPI_INT, first, MPI_COMM_WORLD);
      if (rank == first) std::fputs(text, stderr);
    } else {
      MPI_Allreduce(MPI_IN_PLACE, &code, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    }
    std::free(text);
  }
  MPI_Finalize();
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    print_usage(stderr);
    return tribex::tools::exit_bad_input;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(stdout);
    return tribex::tools::exit_ok;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  for (const auto& c : commands) {
    if (name == c.name && name == "run") {
      // Before anything is read or written (solver/run/stop_signal.hpp); a rank of mpirun also takes its
      // launcher's SIGCONT, the first signal of the kill sequence that ends the job.
      tribex::solver::install_stop_handlers(launched_by_mpirun());
      return run_parallel(argc, argv, c, args);
    }
    if (name == c.name) return tribex::cli::run_mapping_errors([&] { return c.run(args); });
  }
  std::vector<std::string> names;
  for (const auto& c : commands) names.emplace_back(c.name);
  const std::string hint = tribex::inputs::closest_match(name, names);
  std::fprintf(stderr, "tribex: unknown command '%s'%s (tribex --help lists them)\n", name.c_str(),
               hint.empty() ? "" : (" (did you mean '" + hint + "'?)").c_str());
  return tribex::tools::exit_bad_input;
}
