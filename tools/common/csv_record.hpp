// SPDX-License-Identifier: MIT
// A measured record: a CSV file with a header row, one column per quantity, optional units in
// brackets (`time[s],position[nm],voltage[V]`; forces as `normal_force[nN],friction_force[nN]`, with
// `load` and `friction` read as those). Values are converted to SI on reading; every
// problem is a tools::BadInput naming `file:line` and the fix.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "inputs/units.hpp"

namespace tribex::tools {

struct CsvColumn {
  std::vector<double> values;  // SI (volts for a voltage column)
  std::string unit;            // as written in the header, "" when none was given
};

/// The column name a header cell stands for: `load` is read as `normal_force` and `friction` as
/// `friction_force` (the convention of friction-test and fit); every other name is itself.
std::string canonical_column_name(const std::string& name);

class CsvRecord {
 public:
  /// Reads `path`; throws tools::BadInput on a missing file, missing header, ragged rows or
  /// non-numeric cells (file:line in the message).
  static CsvRecord read(const std::string& path);
  /// Builds a record in memory (used by the synthetic generators); values are SI.
  CsvRecord(std::string path, std::vector<std::pair<std::string, CsvColumn>> columns);

  const std::string& path() const { return path_; }
  std::size_t size() const { return rows_; }
  bool has(const std::string& name) const { return columns_.count(name) != 0; }
  /// The column `name` in SI, checked against dimension `d` (a column without a unit is taken
  /// as SI). Throws BadInput naming the columns present when it is missing.
  const std::vector<double>& column(const std::string& name, inputs::Dimension d) const;
  /// A voltage column: unit V, mV or kV (the unit parser has no volts: they are not a
  /// mass-length-time dimension). Returns volts.
  const std::vector<double>& voltage(const std::string& name) const;
  /// Throws BadInput unless the column strictly increases (file:line of the first offender).
  void require_increasing(const std::string& name) const;
  /// Throws BadInput unless the record has at least `n` rows.
  void require_rows(std::size_t n, const std::string& why) const;
  /// `file:line` of data row `i` (0-based; the header is line 1).
  std::string where(std::size_t i) const;
  /// Writes the record as CSV with units in the header (positions in nm, time in s, voltages in V).
  void write(const std::string& path) const;
  std::vector<std::string> names() const;

 private:
  CsvRecord() = default;
  std::string path_;
  std::map<std::string, CsvColumn> columns_;
  std::vector<std::string> order_;  // header order (canonical names)
  std::map<std::string, std::string> written_;  // canonical name -> the synonym the header used
  std::string display(const std::string& name) const;  // for messages: 'load' (read as 'normal_force')
  std::vector<std::size_t> lines_;  // file line of each row (comment/blank lines skipped)
  std::size_t rows_ = 0;
};

}  // namespace tribex::tools
