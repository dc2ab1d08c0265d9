// SPDX-License-Identifier: MIT
#include "solver/output/summary_writer.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "solver/errors.hpp"
#include "solver/output/json.hpp"
#include "solver/output/output_tables.hpp"

namespace tribex::solver {

namespace {
// JSON has no NaN/inf: null for them; 17 digits so that the figures round-trip.
std::string number(double x) { return json_number(x, 17); }

// "name": "unit" of a table's rows that have a unit, comma-separated.
template <class T>
std::string units(std::span<const Field<T>> table) {
  std::string out;
  for (const Field<T>& f : table)
    if (!f.unit.empty())
      out += (out.empty() ? "" : ", ") + json_string(std::string(f.name)) + ": " + json_string(std::string(f.unit));
  return out;
}

}  // namespace

void reserve_summary_json(const std::string& path, std::size_t bytes) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) throw output_failure(tmp, errno);
  const std::string blanks(bytes, ' ');
  const bool written = std::fwrite(blanks.data(), 1, blanks.size(), f) == blanks.size() && std::fflush(f) == 0;
  const int err = errno;
  if (std::fclose(f) != 0 || !written) {
    const int e = written ? errno : err;
    std::remove(tmp.c_str());
    throw output_failure(tmp, e);
  }
}

void write_summary_json(const std::string& path, const RunSummary& s) {
  // One key per line in table order (output_tables.cpp), then "units": the unit of every key that
  // is a quantity, and of the fields of the energies object, of a warnings entry and of a rank_counts entry.
  std::string text = "{\n";
  for (const Field<RunSummary>& k : summary_fields())
    text += "  \"" + std::string(k.name) + "\": " + (k.json ? k.json(s) : number(k.get(s))) + ",\n";
  std::string parameter_units;  // "-" for a dimensionless parameter
  for (const inputs::DeckParameter& p : s.parameters)
    parameter_units += (parameter_units.empty() ? "" : ", ") + json_string(p.name) + ": " +
                       json_string(p.unit.empty() ? "-" : p.unit);
  text += "  \"units\": {" + units(summary_fields()) + ", \"energies\": {" + units(energy_fields()) +
          "}, \"warnings\": {" + units(warning_fields()) + "}, \"rank_counts\": {" + units(rank_count_fields()) +
          "}, \"parameters\": {" + parameter_units + "}}\n}\n";
  // Written over the reserved blanks (reserve_summary_json) without truncating first, so that a full
  // disk needs no new block, then cut to its length; whole or not at all: a full disk keeps the
  // earlier summary.json (if any) and says so.
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "r+");
  if (!f) f = std::fopen(tmp.c_str(), "w");
  if (!f) throw output_failure(tmp, errno);
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0 &&
                       ftruncate(fileno(f), static_cast<off_t>(text.size())) == 0;
  const int write_errno = errno;
  if (std::fclose(f) != 0 || !written) {
    const int err = written ? errno : write_errno;
    std::remove(tmp.c_str());
    throw output_failure(path, err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw output_failure(path, errno);
}

}  // namespace tribex::solver
