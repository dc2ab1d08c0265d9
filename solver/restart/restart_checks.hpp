// SPDX-License-Identifier: MIT
// A restart file's scalars checked before the run uses them (issue 54, items 9 and 17): the step,
// the time and the time steps, the output schedules' next times and the recorded wall times must be
// finite and consistent with the deck's time span; an edited or damaged file is exit 2 naming the
// dataset, before any output file is touched.
#pragma once

#include <string>

#include "inputs/deck.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {

/// Throws SetupError `PATH: error: restart dataset 'NAME' ...` for the first value out of bounds.
/// has_results: the deck writes results (results_next is a time, else 0).
void check_restart_values(const StateArchive& archive, const inputs::TimeControlSpec& time_control, bool has_results,
                          const std::string& path);

}  // namespace tribex::solver
