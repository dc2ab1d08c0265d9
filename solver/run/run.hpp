// SPDX-License-Identifier: MIT
// A whole run of a deck: set-up, pre-flight report, the time loop with history/field output,
// progress, signals, and the closing summary. This is what `tribex run` calls.
#pragma once

#include <string>
#include <vector>

#include "solver/output/run_summary.hpp"

#include "inputs/deck.hpp"

namespace tribex::solver {

struct RunOptions {
  std::string output_directory;  // created if missing
  bool quiet = false;            // no progress line, no echo to the terminal (log.txt still written)
  bool check_only = false;       // set up, print the pre-flight report, do not integrate
  std::string restart_path;      // non-empty: resume from this restart file (same deck; any rank count: restart/restart_remap.hpp)
  bool restart_allow_changed = false;  // resume although the deck or mesh differ from the restart file's
  long stop_at_step = -1;        // >= 0: stop as if interrupted after this step (writes a restart file)
  double heartbeat_seconds = 60; // stdout not a terminal (batch, pipe): a progress line to stdout and log.txt
                                 // this often (wall time); 0: none
};

/// Runs `deck`. Bad input (deck vs mesh) throws SetupError/MeshError before anything is written
/// to the output folder except log.txt; a numerical failure is returned as exit code 3 with every
/// output file flushed and valid; SIGINT/SIGTERM finish the current step and return 130.
RunSummary run_deck(const inputs::Deck& deck, const RunOptions& options);

}  // namespace tribex::solver
