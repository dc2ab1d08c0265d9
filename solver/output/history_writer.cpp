// SPDX-License-Identifier: MIT
#include "solver/output/history_writer.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "solver/errors.hpp"

namespace tribex::solver {

const std::vector<std::string>& HistoryWriter::standard_columns() {
  static const std::vector<std::string> columns = {
      "time", "dt", "kinetic_energy", "internal_energy", "hourglass_energy", "external_work",
      "silent_boundary_dissipation", "contact_work", "energy_error", "contact_normal_force",
      "contact_tangential_force", "contact_area", "contact_nodes", "damping_dissipation", "viscous_dissipation",
      "contact_radius", "contact_radius_max", "contact_max_penetration", "momentum_x", "momentum_y", "momentum_z",
      "contact_radius_edge",
      // interface models (contact/models/): forces on the slave surfaces, N; tau* x contact area, N;
      // adhesive potential, J; junction dissipation rate, W
      "adhesive_force", "compressive_force", "friction_force", "tau_star_times_area", "adhesion_energy",
      "friction_power",
      // elliptic-pressure fit of the contact radius (contact/contact_manager.cpp pressure_fit_radius), m
      "contact_radius_pressure_fit",
      // rough-surface (GW) model: real contact area A_c, m^2; asperities in contact; normal force over
      // the nominal area within reach of the law, Pa
      "real_contact_area", "asperity_contacts", "apparent_pressure"};
  return columns;
}

HistoryWriter::HistoryWriter(const std::string& path, const std::vector<std::string>& extra_columns, long resume_step)
    : path_(path) {
  std::string header = "step";
  for (const auto& c : standard_columns()) header += "," + c;
  for (const auto& c : extra_columns) header += "," + c;
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
  columns_ = standard_columns().size() + extra_columns.size();
}

HistoryWriter::~HistoryWriter() {
  if (file_) std::fclose(file_);
}

void HistoryWriter::write_row(long step, const std::vector<double>& values) {
  std::fprintf(file_, "%ld", step);
  for (std::size_t k = 0; k < columns_; ++k) std::fprintf(file_, ",%.17g", k < values.size() ? values[k] : 0.0);
  std::fputc('\n', file_);
  if (std::fflush(file_) != 0 || std::ferror(file_)) throw output_failure(path_, errno);
}

}  // namespace tribex::solver
