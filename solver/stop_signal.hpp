// SPDX-License-Identifier: MIT
// SIGINT/SIGTERM for `tribex run`: installed at process start (tools/cli/main.cpp), so that a signal at
// any moment, set-up included, is recorded instead of killing the process half-way through writing a
// file. The run looks at it at fixed points: during set-up (before any output exists: exit 130, nothing
// written) and after every step (the loop finishes the step, writes valid outputs and a restart file).
#pragma once

#include <stdexcept>

namespace tribex::solver {

/// Installs the recording handlers (idempotent).
void install_stop_handlers();

/// The signal received since the start (SIGINT, SIGTERM), or 0.
int stop_signal();

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
