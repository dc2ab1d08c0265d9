// SPDX-License-Identifier: MIT
// CSV and JSON files of a PSTD run (units in the column names: nm, uN, um^2).
#pragma once

#include <string>
#include <vector>

#include "tools/pstd/events.hpp"
#include "tools/pstd/model.hpp"
#include "tools/pstd/stepping.hpp"

namespace tribex::pstd {

/// One summit in contact after the initial press-in (for initial_contacts.csv).
struct ContactReport {
  int copy = 0;
  std::size_t segment = 0;
  double x = 0.0, interference = 0.0, radius = 0.0, half_width = 0.0, force = 0.0;  // SI
};
std::vector<ContactReport> initial_contacts(const Model& model, double normal_force);

struct StudyRow {
  std::size_t copies = 0;
  double apparent_length = 0.0;  // m
  double normal_force = 0.0;     // N
  Run run;
  std::vector<PstdEvent> events;
  double wall_seconds = 0.0;
};

void write_trajectory_csv(const std::string& path, const Run& run, const std::vector<PstdEvent>& events);
void write_events_csv(const std::string& path, const std::vector<PstdEvent>& events);
void write_contacts_csv(const std::string& path, const std::vector<ContactReport>& contacts);
void write_study_csv(const std::string& path, const std::vector<StudyRow>& rows);
void write_study_trajectories_csv(const std::string& path, const std::vector<StudyRow>& rows);

}  // namespace tribex::pstd
