// SPDX-License-Identifier: MIT
// SIGINT/SIGTERM for `tribex run`: installed at process start (tools/cli/main.cpp), so that a signal at
// any moment, set-up included, is recorded instead of killing the process half-way through writing a
// file. The run looks at it at fixed points: during set-up (before any output exists: exit 130, nothing
// written) and after every step (the loop finishes the step, writes valid outputs and a restart file).
//
// Under Open MPI's mpirun (4.1) a SIGTERM or SIGINT to mpirun is not forwarded: mpirun ends the job by
// sending each rank SIGCONT, then SIGTERM odls_base_sigkill_timeout seconds later (1 by default), then
// SIGKILL as long again (orte/mca/odls/base/odls_base_default_fns.c, kill_local_procs). A rank that
// waited for the SIGTERM had 1 s to stop, and with the timeout raised a run could end normally before
// the SIGTERM came. So a rank started by mpirun also takes a SIGCONT sent by its parent (mpirun or
// orted) as the stop, unless it follows a job-control stop (SIGTSTP, which mpirun forwards and this
// handler records before stopping): the ranks then have 2 x the timeout from mpirun's signal. SIGUSR1,
// which mpirun forwards at once, stops a run too; mpirun then exits with the ranks' code, 130
// (docs/architecture.md "Signals").
#pragma once

#include <stdexcept>
#include <string>

namespace tribex::solver {

/// Installs the recording handlers (idempotent). `under_mpirun`: the process is a rank started by
/// mpirun/mpiexec, whose SIGCONT from the parent means the job is being ended.
void install_stop_handlers(bool under_mpirun = false);

/// The signal received since the start (SIGINT, SIGTERM, SIGUSR1, or SIGCONT from mpirun), or 0.
int stop_signal();

/// Seconds since that signal arrived (0 when none): what a stop took, its running step included.
double seconds_since_stop_signal();

/// The stop in words for log.txt: "SIGTERM", "SIGCONT from mpirun (the start of its kill sequence)", ...
std::string stop_signal_text(int signal);

/// Fault injection for the tests (tests/cli/CMakeLists.txt): raises SIGTERM when the environment variable
/// TRIBEX_FAULT_SIGNAL names this point ("setup": the start of the run; "outputs": the output files just
/// opened), so that a signal at those moments is tested without racing a real one.
void fault_signal_point(const char* point);

/// Thrown when a stop arrives during set-up, before any output file exists: exit 130, nothing written.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tribex::solver
