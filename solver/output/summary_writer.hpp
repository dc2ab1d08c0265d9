// SPDX-License-Identifier: MIT
// summary.json: final figures of a run (valid JSON, one object).
#pragma once

#include <string>

#include "solver/output/run_summary.hpp"

namespace tribex::solver {

/// Reserves disk space for the closing summary.json: its temporary file, 16 KiB of blanks, made
/// when the outputs are open. write_summary_json truncates and rewrites that file, so the pages it
/// frees are the ones it needs: a disk that fills during the loop still gets its summary.json (the
/// run's status says why it stopped). Best effort: a reservation that cannot be made is skipped.
void reserve_summary_json(const std::string& path);

/// Writes `summary` (keys, order and units: summary_fields(), solver/output/output_tables.cpp)
/// through a temporary file and a rename: whole or not at all.
void write_summary_json(const std::string& path, const RunSummary& summary);

}  // namespace tribex::solver
