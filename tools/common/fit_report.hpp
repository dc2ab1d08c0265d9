// SPDX-License-Identifier: MIT
// The fitted quantities of a data-reduction command (friction-test, fit) and how they are printed: one JSON object
// (`--json`: every quantity as {"value", "uncertainty", "unit"}, SI) or a readable table.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace tribex::tools {

struct ReportedQuantity {
  std::string name;         // JSON key, e.g. "friction_force"
  double value = 0.0;       // SI
  double uncertainty = -1;  // 1 sigma, SI; < 0 when not applicable (exact or input)
  std::string unit;         // SI unit, "" for dimensionless
  std::string note;         // shown in the table only
};

struct FitReport {
  std::string command;  // "calibrate", "static", "dynamic"
  std::vector<std::pair<std::string, std::string>> text;  // string fields (file, ...)
  std::vector<ReportedQuantity> quantities;
  std::vector<std::pair<std::string, std::vector<std::vector<double>>>> tables;  // e.g. slip events, rows

  void add(std::string name, double value, double uncertainty, std::string unit, std::string note = "") {
    quantities.push_back({std::move(name), value, uncertainty, std::move(unit), std::move(note)});
  }
  const ReportedQuantity& get(const std::string& name) const;
  std::string json() const;
  void print_table(std::FILE* to) const;
};

}  // namespace tribex::tools
