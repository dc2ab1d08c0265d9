// SPDX-License-Identifier: MIT
// The closing figures of a run, as run_deck returns them and summary.json writes them (the keys:
// summary_fields() in solver/output/output_tables.cpp).
#pragma once

#include <string>
#include <vector>

#include "inputs/deck.hpp"
#include "solver/energy.hpp"
#include "solver/guards/run_warning.hpp"
#include "solver/setup/mass_scaling.hpp"
#include "solver/output/run_identity.hpp"
#include "solver/parallel/rank_counts.hpp"

namespace tribex::solver {

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
  double contact_balance = 1.0;  // the busiest rank's contact pairs over the even share (ContactManager::Work)
  int elements = 0;
  int nodes = 0;
  double initial_stable_time_step = 0.0;  // s, the stable step at t = 0 (before the scale factor)
  int controlling_element = -1;            // the element that set it (0-based; summary.json: 1-based)
  Energies energies;                       // the energy ledger at the end
  std::vector<RunWarning> warnings;  // set-up and run guards (solver/guards/README.md), in the order raised
  MassScalingReport mass_scaling;    // `begin mass scaling` (inactive: summary.json null)
  std::vector<parallel::RankCounts> rank_counts;  // every rank's counts, in rank order (rank 0; others: empty)
  std::vector<inputs::DeckParameter> parameters;  // the deck's {NAME = ...} with --set applied (SI)
};

}  // namespace tribex::solver
