// SPDX-License-Identifier: MIT
// summary.json: final figures of a run (valid JSON, one object).
#pragma once

#include <string>

#include "solver/energy.hpp"
#include "solver/output/run_summary.hpp"
#include "solver/stable_time_step.hpp"

namespace tribex::solver {

void write_summary_json(const std::string& path, const RunSummary& summary, const Energies& energies,
                        const StableStep& initial_stable_step);

}  // namespace tribex::solver
