// SPDX-License-Identifier: MIT
// A whole run of a deck: set-up, pre-flight report, the time loop with history/field output,
// progress, signals, and the closing summary. This is what `tribex run` calls.
#pragma once

#include <string>
#include <vector>

#include "solver/guards/run_warning.hpp"
#include "solver/output/run_identity.hpp"

#include "inputs/deck.hpp"

namespace tribex::solver {

struct RunOptions {
  std::string output_directory;  // created if missing
  bool quiet = false;            // no progress line, no echo to the terminal (log.txt still written)
  bool check_only = false;       // set up, print the pre-flight report, do not integrate
  std::string restart_path;      // non-empty: resume from this restart file (same deck, same rank count)
  bool restart_allow_changed = false;  // resume although the deck or mesh differ from the restart file's
  long stop_at_step = -1;        // >= 0: stop as if interrupted after this step (writes a restart file)
  double heartbeat_seconds = 60; // stdout not a terminal (batch, pipe): a progress line to stdout and log.txt
                                 // this often (wall time); 0: none
};

struct RunSummary {
  RunIdentity identity;          // version, deck and its SHA-256, start time, host, ranks
  int exit_code = 0;             // 0, 3 (numerical failure) or 130 (interrupted)
  std::string status;            // "normal termination", "numerical failure: ...", "interrupted"
  long steps = 0;                 // step index at the end
  long first_step = 0;            // step index this process started from (> 0 when resumed)
  double final_time = 0.0;
  double energy_error = 0.0;
  double wall_seconds = 0.0;
  double loop_seconds = 0.0;
  double ns_per_element_step = 0.0;  // loop time / (elements * (steps - first_step)): this process
  double total_wall_seconds = 0.0;   // all segments of a resumed run (NaN when an earlier one is unknown)
  double total_loop_seconds = 0.0;
  double contact_seconds = 0.0;      // part of the loop spent in contact search and enforcement
  int ranks = 1;                     // MPI ranks of the run
  double communication_seconds = 0.0;  // rank 0's loop time in halo exchange, surface gather, energy sums
  int elements = 0;
  int nodes = 0;
  std::vector<RunWarning> warnings;  // set-up and run guards (solver/guards/README.md), in the order raised
};

/// Runs `deck`. Bad input (deck vs mesh) throws SetupError/MeshError before anything is written
/// to the output folder except log.txt; a numerical failure is returned as exit code 3 with every
/// output file flushed and valid; SIGINT/SIGTERM finish the current step and return 130.
RunSummary run_deck(const inputs::Deck& deck, const RunOptions& options);

}  // namespace tribex::solver
