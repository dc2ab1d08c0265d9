// SPDX-License-Identifier: MIT
// When and where restart files are written (`begin restart output`): every `step increment` steps
// and/or every `wall time increment` seconds of wall-clock time, into the ring restart_0.h5 ...
// restart_<ring-1>.h5 of the output folder; OUT/restart.h5 is then replaced by a hard link to the
// newest one, so `tribex run DECK --restart OUT/restart.h5` always resumes from the latest state.
#pragma once

#include <chrono>
#include <string>

#include "inputs/deck.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {

class RestartOutput {
 public:
  /// run_id: written into every restart file (attribute `run_id`), so that a resumed run knows its run.
  RestartOutput(const inputs::RestartOutputSpec& spec, std::string directory, std::string run_id);

  /// Is a restart file due after `step`? Collective in a parallel run (rank 0's wall clock decides).
  bool due(long step);
  /// Writes the archive into the next file of the ring and points restart.h5 at it; returns its path.
  std::string write(const StateArchive& archive);

 private:
  inputs::RestartOutputSpec spec_;
  std::string directory_;
  std::string run_id_;
  int next_slot_ = 0;
  std::chrono::steady_clock::time_point last_write_;
};

}  // namespace tribex::solver
