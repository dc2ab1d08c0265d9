// SPDX-License-Identifier: MIT
// Small helpers shared by the text-format height-map readers (internal to mesh/afm).
#pragma once

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm::detail {

inline std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

/// A whole-token real number, or nothing (no partial parses like "1.5abc").
inline std::optional<double> to_number(const std::string& text) {
  const std::string t = trim(text);
  double v = 0.0;
  const char* first = t.data();
  if (!t.empty() && t[0] == '+') ++first;
  auto [p, ec] = std::from_chars(first, t.data() + t.size(), v);
  if (ec != std::errc() || p != t.data() + t.size() || t.empty()) return std::nullopt;
  return v;
}

/// Splits on blanks/tabs (and commas when `commas`).
inline std::vector<std::string> split_fields(const std::string& line, bool commas = false) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == '\r' || (commas && c == ',')) {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur.push_back(c);
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

/// The lines of a text file, trimmed, with their 1-based numbers (LF or CRLF endings):
///   LineReader lines(text); std::string line; int n;
///   while (lines.next(line, n)) { ... }
class LineReader {
 public:
  explicit LineReader(const std::string& text) : text_(text) {}
  bool next(std::string& line, int& line_no) {
    if (pos_ >= text_.size()) return false;
    std::size_t eol = text_.find('\n', pos_);
    if (eol == std::string::npos) eol = text_.size();
    line = trim(text_.substr(pos_, eol - pos_));
    pos_ = eol + 1;
    line_no = ++line_no_;
    return true;
  }

 private:
  const std::string& text_;
  std::size_t pos_ = 0;
  int line_no_ = 0;
};

/// A non-empty line of a text export, with "path:LINE" for the messages.
struct TextLine {
  std::string text, where;
  int number = 0;
};

/// Every non-empty line of a text export whose header lines start with '#': `comment(TextLine)` for
/// those, `data(TextLine)` for the others. Returns the number of the last line read.
template <class Comment, class Data>
int for_each_line(const std::string& text, const std::string& path, Comment comment, Data data) {
  LineReader lines(text);
  TextLine line;
  while (lines.next(line.text, line.number)) {
    if (line.text.empty()) continue;
    line.where = path + ":" + std::to_string(line.number);
    if (line.text[0] == '#')
      comment(line);
    else
      data(line);
  }
  return line.number;
}

/// Field `i` of a data row as a finite number; a MeshError naming the row and the column otherwise.
inline double finite_field(const std::vector<std::string>& fields, std::size_t i, const std::string& where) {
  const auto v = to_number(fields[i]);
  if (!v || !std::isfinite(*v))
    throw MeshError(where + ": column " + std::to_string(i + 1) + ": expected a finite number, got '" +
                    fields[i].substr(0, 30) + "'");
  return *v;
}

/// Metres per unit for the SI-prefixed length units text exports use ("m", "nm", "um", "µm", "pm", "mm").
inline std::optional<double> metres_per(const std::string& unit_text) {
  const std::string u = trim(unit_text);
  if (u == "m") return 1.0;
  if (u == "mm") return 1e-3;
  if (u == "um" || u == "\xc2\xb5m" || u == "\xb5m" || u == "~m") return 1e-6;
  if (u == "nm") return 1e-9;
  if (u == "pm") return 1e-12;
  if (u == "A" || u == "\xc3\x85") return 1e-10;
  return std::nullopt;
}

}  // namespace tribex::mesh::afm::detail
