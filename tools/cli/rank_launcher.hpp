// SPDX-License-Identifier: MIT
// `tribex run --ranks N DECK ...`: starts the run under mpirun and stays its parent, so that the command
// a user or a batch script signals ends as promised (issue 54, item 10). Open MPI's mpirun, sent SIGTERM
// or SIGINT itself, ends the ranks with its kill sequence and exits 1 whatever they return; this launcher
// forwards a SIGINT/SIGTERM/SIGUSR1 it receives to mpirun as SIGUSR1 (which mpirun forwards to the ranks at
// once: they stop after their step, write valid outputs and a restart file) and exits with the ranks'
// code: 130 (docs/architecture.md "Signals").
#pragma once

#include <string>
#include <vector>

namespace tribex::cli {

/// Runs `mpirun -np ranks [--oversubscribe] <this tribex> run <run_args>` with stdin from /dev/null in
/// its own process group (a terminal's Ctrl-C reaches this process only), forwards stop signals as
/// SIGUSR1 and returns mpirun's exit code (128 + signal when it was killed). Throws tools::BadInput when
/// mpirun is missing or refuses to start as root.
int run_under_mpirun(int ranks, const std::vector<std::string>& run_args);

/// `args` without `--ranks N` / `--ranks=N`.
std::vector<std::string> without_ranks_option(const std::vector<std::string>& args);

}  // namespace tribex::cli
