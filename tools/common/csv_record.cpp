// SPDX-License-Identifier: MIT
#include "tools/common/csv_record.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "tools/common/errors.hpp"
#include "tools/common/text_file.hpp"

namespace tribex::tools {
namespace {



std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// Factor to volts for "V", "mV", "kV", "uV"; 0 when the unit is not a voltage.
double volt_factor(const std::string& unit) {
  if (unit == "V") return 1.0;
  if (unit == "mV") return 1e-3;
  if (unit == "kV") return 1e3;
  if (unit == "uV") return 1e-6;
  return 0.0;
}

// Factor to SI of a header unit; voltages are accepted here and checked by CsvRecord::voltage().
double unit_factor(const std::string& unit, const std::string& where) {
  if (unit.empty()) return 1.0;
  if (double v = volt_factor(unit); v != 0.0) return v;
  std::string error;
  auto q = inputs::parse_unit(unit, &error);
  if (!q) throw BadInput(where + ": unit [" + unit + "]: " + error + " (write e.g. time[s],position[nm])");
  return q->value;
}

}  // namespace

CsvRecord::CsvRecord(std::string path, std::vector<std::pair<std::string, CsvColumn>> columns) : path_(std::move(path)) {
  for (auto& [name, c] : columns) {
    order_.push_back(name);
    rows_ = c.values.size();
    columns_[name] = std::move(c);
  }
  for (std::size_t i = 0; i < rows_; ++i) lines_.push_back(i + 2);
}

std::string canonical_column_name(const std::string& name) {
  // The one convention of `tribex friction-test` and `tribex fit` (tools/common/README.md): a force
  // pair is normal_force, friction_force; `load` and `friction` are read as those.
  static const std::map<std::string, std::string> synonyms = {{"load", "normal_force"}, {"friction", "friction_force"}};
  const auto it = synonyms.find(name);
  return it == synonyms.end() ? name : it->second;
}

std::string CsvRecord::display(const std::string& name) const {
  const auto it = written_.find(name);
  if (it == written_.end()) return "'" + name + "'";
  return "'" + it->second + "' (read as '" + name + "')";
}

CsvRecord CsvRecord::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw BadInput(path + ": cannot open the file (check the path)");
  CsvRecord r;
  r.path_ = path;
  std::string line;
  std::size_t line_no = 0;
  std::vector<double> factors;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::string where = path + ":" + std::to_string(line_no);
    auto cells = split(t);
    if (!have_header) {
      for (const auto& cell : cells) {
        std::string name = cell, unit;
        if (auto open = cell.find('['); open != std::string::npos) {
          const auto close = cell.find(']', open);
          if (close == std::string::npos || close != cell.size() - 1)
            throw BadInput(where + ": header cell '" + cell + "' has an unclosed unit bracket (write name[unit])");
          name = trim(cell.substr(0, open));
          unit = trim(cell.substr(open + 1, close - open - 1));
        }
        if (name.empty()) throw BadInput(where + ": empty column name in the header (every column needs a name)");
        const bool first_char_digit = (name[0] >= '0' && name[0] <= '9') || name[0] == '-' || name[0] == '.';
        if (first_char_digit)
          throw BadInput(where + ": the first line must be a header such as time[s],position[nm], found '" + t + "'");
        const std::string written = name;
        name = canonical_column_name(name);
        if (r.columns_.count(name))
          throw BadInput(where + ": column '" + written + "' appears twice in the header" +
                         (written == name ? std::string() : " (as '" + name + "' or a synonym of it)"));
        if (written != name) r.written_[name] = written;
        r.columns_[name].unit = unit;
        r.order_.push_back(name);
        factors.push_back(unit_factor(unit, where));
      }
      have_header = true;
      continue;
    }
    if (cells.size() != r.order_.size())
      throw BadInput(where + ": " + std::to_string(cells.size()) + " cells but the header has " +
                     std::to_string(r.order_.size()) + " columns (every row needs one value per column)");
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string& s = cells[c];
      double v = 0.0;
      auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      if (s.empty() || ec != std::errc{} || ptr != s.data() + s.size() || !std::isfinite(v))
        throw BadInput(where + ": column '" + r.order_[c] + "': '" + s +
                       "' is not a number (write plain numbers; units go in the header)");
      r.columns_[r.order_[c]].values.push_back(v * factors[c]);
    }
    r.lines_.push_back(line_no);
    ++r.rows_;
  }
  if (!have_header) throw BadInput(path + ": empty file (expected a header row such as time[s],position[nm])");
  return r;
}

std::vector<std::string> CsvRecord::names() const { return order_; }

std::string CsvRecord::where(std::size_t i) const {
  return path_ + ":" + std::to_string(i < lines_.size() ? lines_[i] : 0);
}

const std::vector<double>& CsvRecord::column(const std::string& name, inputs::Dimension d) const {
  auto it = columns_.find(name);
  if (it == columns_.end()) {
    std::string have;
    for (const auto& n : order_) have += (have.empty() ? "" : ",") + n;
    throw BadInput(path_ + ":1: missing column '" + name + "' (the header has: " + have +
                   "; add a column '" + name + "[unit]')");
  }
  const auto& unit = it->second.unit;
  if (!unit.empty()) {
    std::string error;
    auto q = inputs::parse_unit(unit, &error);
    if (!q || !(q->dimension == d))
      throw BadInput(path_ + ":1: column " + display(name) + " has unit [" + unit + "] but needs a " + d.str() +
                     " unit");
  }
  return it->second.values;
}

const std::vector<double>& CsvRecord::voltage(const std::string& name) const {
  auto it = columns_.find(name);
  if (it == columns_.end()) return column(name, inputs::dim::none);  // throws the missing-column error
  if (!it->second.unit.empty() && volt_factor(it->second.unit) == 0.0)
    throw BadInput(path_ + ":1: column '" + name + "' has unit [" + it->second.unit + "] but needs V, mV or kV");
  return it->second.values;
}

void CsvRecord::require_increasing(const std::string& name) const {
  const auto& v = columns_.at(name).values;
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1]))
      throw BadInput(where(i) + ": column '" + name + "' does not increase (" + std::to_string(v[i]) +
                     " after " + std::to_string(v[i - 1]) + "); sort the rows by " + name +
                     " and drop repeated samples");
}

void CsvRecord::require_rows(std::size_t n, const std::string& why) const {
  if (rows_ < n)
    throw BadInput(path_ + ": " + std::to_string(rows_) + " data rows, at least " + std::to_string(n) +
                   " needed " + why);
}

void CsvRecord::write(const std::string& path) const {
  std::ostringstream out;  // written whole through write_text_file (a regular file only, never half-written)
  std::vector<double> factors;
  for (std::size_t c = 0; c < order_.size(); ++c) {
    const auto& col = columns_.at(order_[c]);
    out << (c ? "," : "") << order_[c];
    if (!col.unit.empty()) out << "[" << col.unit << "]";
    factors.push_back(unit_factor(col.unit, path));
  }
  out << "\n";
  char buf[64];
  for (std::size_t i = 0; i < rows_; ++i) {
    for (std::size_t c = 0; c < order_.size(); ++c) {
      std::snprintf(buf, sizeof buf, "%.10g", columns_.at(order_[c]).values[i] / factors[c]);
      out << (c ? "," : "") << buf;
    }
    out << "\n";
  }
  write_text_file(path, out.str());
}

}  // namespace tribex::tools
