// SPDX-License-Identifier: MIT
#include "tools/common/fit_report.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tribex::tools {
namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";  // JSON has no NaN/inf
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

const ReportedQuantity& FitReport::get(const std::string& name) const {
  for (const auto& q : quantities)
    if (q.name == name) return q;
  throw std::out_of_range("no quantity " + name);
}

std::string FitReport::json() const {
  std::ostringstream o;
  o << "{\"command\": \"" << escape(command) << "\"";
  for (const auto& [k, v] : text) o << ", \"" << escape(k) << "\": \"" << escape(v) << "\"";
  for (const auto& q : quantities) {
    o << ", \"" << escape(q.name) << "\": {\"value\": " << number(q.value);
    if (q.uncertainty >= 0) o << ", \"uncertainty\": " << number(q.uncertainty);
    o << ", \"unit\": \"" << escape(q.unit) << "\"}";
  }
  for (const auto& [k, rows] : tables) {
    o << ", \"" << escape(k) << "\": [";
    for (std::size_t r = 0; r < rows.size(); ++r) {
      o << (r ? ", [" : "[");
      for (std::size_t c = 0; c < rows[r].size(); ++c) o << (c ? ", " : "") << number(rows[r][c]);
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
