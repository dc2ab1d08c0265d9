// SPDX-License-Identifier: MIT
#include "solver/output/history_writer.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "solver/errors.hpp"

namespace tribex::solver {

namespace {

// A CSV field: quoted when it holds a comma or a quote (RFC 4180).
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void write_units_file(const std::string& path, const std::vector<ColumnInfo>& columns) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw SetupError("cannot write " + path + ": " + std::strerror(errno));
  std::fputs("column,unit,definition\n", f);
  for (const auto& c : columns)
    std::fprintf(f, "%s,%s,%s\n", c.name.c_str(), csv_field(c.unit).c_str(), csv_field(c.definition).c_str());
  const bool ok = !std::ferror(f);
  const int err = errno;
  if (std::fclose(f) != 0 || !ok) throw output_failure(path, ok ? errno : err);
}

}  // namespace

std::string history_units_path(const std::string& history_path) {
  const auto slash = history_path.find_last_of('/');
  return (slash == std::string::npos ? std::string() : history_path.substr(0, slash + 1)) + "history_columns.csv";
}

HistoryWriter::HistoryWriter(const std::string& path, const std::vector<ColumnInfo>& columns, long resume_step)
    : path_(path) {
  if (columns.empty() || columns.front().name != "step") throw std::logic_error("history.csv: the first column is 'step'");
  std::string header;
  for (const auto& c : columns) header += (header.empty() ? "" : ",") + c.name;
  std::string kept;  // rows of the interrupted run before the restart step
  if (resume_step >= 0) {
    std::ifstream old(path);
    std::string line;
    if (std::getline(old, line) && line == header)
      while (std::getline(old, line) && !line.empty() && std::strtol(line.c_str(), nullptr, 10) < resume_step) kept += line + "\n";
  }
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw SetupError("cannot write " + path + ": " + std::strerror(errno));
  std::fputs(header.c_str(), file_);
  std::fputc('\n', file_);
  std::fputs(kept.c_str(), file_);
  std::fflush(file_);
  columns_ = columns.size() - 1;
  write_units_file(history_units_path(path), columns);
}

HistoryWriter::~HistoryWriter() {
  if (file_) std::fclose(file_);
}

void HistoryWriter::write_row(long step, const std::vector<double>& values) {
  if (values.size() != columns_)
    throw std::logic_error("history.csv: a row of " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_) + " columns");
  std::fprintf(file_, "%ld", step);
  for (double v : values) std::fprintf(file_, ",%.17g", v);
  std::fputc('\n', file_);
  if (std::fflush(file_) != 0 || std::ferror(file_)) throw output_failure(path_, errno);
}

}  // namespace tribex::solver
