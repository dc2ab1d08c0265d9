// SPDX-License-Identifier: MIT
// history.csv: one header row of column names, one row per history interval; beside it
// history_columns.csv (`column,unit,definition`, one row per column of history.csv) so that the
// units stay out of the header existing scripts read. The columns and their definitions come from
// solver/output/history_columns.hpp. SI units throughout; 17 significant digits so that runs can
// be compared to round-off. Flushed after every row.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "solver/output/history_columns.hpp"

namespace tribex::solver {

class HistoryWriter {
 public:
  /// Opens `path`, writes the header of `columns` (the first is `step`) and the units file beside it.
  /// `resume_step` >= 0 (a restarted run): the rows of an existing `path` with the same header and
  /// step < resume_step are kept, so the file reads as if the run had not been interrupted.
  HistoryWriter(const std::string& path, const std::vector<ColumnInfo>& columns, long resume_step = -1);
  ~HistoryWriter();
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  /// One row: the values of every column after `step`, in header order (std::logic_error if their
  /// count differs: a column is never padded or dropped).
  void write_row(long step, const std::vector<double>& values);

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
  std::size_t columns_ = 0;  // after `step`
};

/// The file history_columns.csv beside `history_path`.
std::string history_units_path(const std::string& history_path);

}  // namespace tribex::solver
