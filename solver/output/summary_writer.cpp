// SPDX-License-Identifier: MIT
#include "solver/output/summary_writer.hpp"

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

void reserve_summary_json(const std::string& path) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) return;
  const std::string blanks(16384, ' ');
  const bool written = std::fwrite(blanks.data(), 1, blanks.size(), f) == blanks.size();
  if (std::fclose(f) != 0 || !written) std::remove(tmp.c_str());
}

void write_summary_json(const std::string& path, const RunSummary& s) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) throw SetupError("cannot write " + path + ": " + std::strerror(errno));
  // One key per line in table order (output_tables.cpp), then "units": the unit of every key that
  // is a quantity, and of the fields of the energies object, of a warnings entry and of a rank_counts entry.
  std::fprintf(f, "{\n");
  for (const Field<RunSummary>& k : summary_fields())
    std::fprintf(f, "  \"%s\": %s,\n", std::string(k.name).c_str(), (k.json ? k.json(s) : number(k.get(s))).c_str());
  std::fprintf(f, "  \"units\": {%s, \"energies\": {%s}, \"warnings\": {%s}, \"rank_counts\": {%s}}\n}\n",
               units(summary_fields()).c_str(), units(energy_fields()).c_str(), units(warning_fields()).c_str(),
               units(rank_count_fields()).c_str());
  // Written whole or not at all: a full disk keeps the earlier summary.json (if any) and says so.
  const bool written = !std::ferror(f);
  const int write_errno = errno;
  if (std::fclose(f) != 0 || !written) {
    const int err = written ? errno : write_errno;
    std::remove(tmp.c_str());
    throw output_failure(path, err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw output_failure(path, errno);
}

}  // namespace tribex::solver
