// SPDX-License-Identifier: MIT
#include "tools/common/fit_report.hpp"

#include <sstream>
#include <stdexcept>

#include "tools/common/json.hpp"

namespace tribex::tools {

const ReportedQuantity& FitReport::get(const std::string& name) const {
  for (const auto& q : quantities)
    if (q.name == name) return q;
  throw std::out_of_range("no quantity " + name);
}

std::string FitReport::json() const {
  std::ostringstream o;
  o << "{\"command\": " << json_string(command);
  for (const auto& [k, v] : text) o << ", " << json_string(k) << ": " << json_string(v);
  for (const auto& q : quantities) {
    o << ", " << json_string(q.name) << ": {\"value\": " << json_number(q.value);
    if (q.uncertainty >= 0) o << ", \"uncertainty\": " << json_number(q.uncertainty);
    o << ", \"unit\": " << json_string(q.unit) << "}";
  }
  for (const auto& [k, rows] : tables) {
    o << ", " << json_string(k) << ": [";
    for (std::size_t r = 0; r < rows.size(); ++r) {
      o << (r ? ", [" : "[");
      for (std::size_t c = 0; c < rows[r].size(); ++c) o << (c ? ", " : "") << json_number(rows[r][c]);
      o << "]";
    }
    o << "]";
  }
  o << "}";
  return o.str();
}

void FitReport::print_table(std::FILE* to) const {
  for (const auto& [k, v] : text) std::fprintf(to, "%-24s %s\n", k.c_str(), v.c_str());
  for (const auto& q : quantities) {
    if (q.uncertainty >= 0)
      std::fprintf(to, "%-24s %14.6g +- %-11.3g %-8s %s\n", q.name.c_str(), q.value, q.uncertainty, q.unit.c_str(),
                   q.note.c_str());
    else
      std::fprintf(to, "%-24s %14.6g    %-11s %-8s %s\n", q.name.c_str(), q.value, "", q.unit.c_str(), q.note.c_str());
  }
}

}  // namespace tribex::tools
