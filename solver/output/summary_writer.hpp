// SPDX-License-Identifier: MIT
// summary.json: final figures of a run (valid JSON, one object).
#pragma once

#include <cstddef>
#include <string>

#include "solver/output/run_summary.hpp"

namespace tribex::solver {

/// Reserves disk space for the closing summary.json: its temporary file, `bytes` blanks, made when
/// the outputs are open. write_summary_json writes over those blanks (no truncation first) and cuts
/// the file to its length, so a disk that fills during the loop still gets its summary.json (the
/// run's status says why it stopped). A reservation that cannot be made throws OutputError (the
/// set-up turns it into exit 2: a run that could not report its end does not start).
void reserve_summary_json(const std::string& path, std::size_t bytes);

/// The reservation for a run of `ranks` ranks: 16 KiB plus 1 KiB a rank (a rank_counts entry is about
/// 0.5 KiB; summary.json of 2 ranks: 3.3 KB).
inline std::size_t summary_json_reserve_bytes(int ranks) { return 16384 + 1024 * static_cast<std::size_t>(ranks); }

/// Writes `summary` (keys, order and units: summary_fields(), solver/output/output_tables.cpp)
/// through a temporary file and a rename: whole or not at all.
void write_summary_json(const std::string& path, const RunSummary& summary);

}  // namespace tribex::solver
