// SPDX-License-Identifier: MIT
// history.csv: one header row, one row per history interval (docs/architecture.md "Outputs"):
//   step,time,dt,kinetic_energy,internal_energy,hourglass_energy,external_work,
//   silent_boundary_dissipation,contact_work,energy_error,contact_normal_force,
//   contact_tangential_force,contact_area,contact_nodes,
// then the other energy terms (damping_dissipation, viscous_dissipation), contact_radius
// (sqrt(area/pi)), contact_radius_max, contact_max_penetration, momentum_{x,y,z},
// contact_radius_edge (where the gap changes sign along slave-face edges), the interface-model
// columns, contact_radius_pressure_fit (zero of the least-squares line p^2 = alpha - beta r^2 through
// the contacting nodes' pressures: the radius of an elliptic, Hertz-like, pressure), the rough-surface
// totals (real_contact_area, asperity_contacts, apparent_pressure; contact/models/README.md), then the requested
// node-set columns <set>_reaction_{x,y,z} and <set>_displacement_{x,y,z}. SI units throughout;
// 17 significant digits so that runs can be compared to round-off. Flushed after every row.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace tribex::solver {

class HistoryWriter {
 public:
  /// Opens `path` and writes the header; `extra_columns` are appended after the standard ones.
  /// `resume_step` >= 0 (a restarted run): the rows of an existing `path` with the same header and
  /// step < resume_step are kept, so the file reads as if the run had not been interrupted.
  HistoryWriter(const std::string& path, const std::vector<std::string>& extra_columns, long resume_step = -1);
  ~HistoryWriter();
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  static const std::vector<std::string>& standard_columns();
  /// One row: values in the order of the header (step first, as an integer).
  void write_row(long step, const std::vector<double>& values);

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
  std::size_t columns_ = 0;
};

}  // namespace tribex::solver
