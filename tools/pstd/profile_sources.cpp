// SPDX-License-Identifier: MIT
#include "tools/pstd/profile_sources.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "inputs/units.hpp"
#include "tools/common/errors.hpp"

namespace tribex::pstd {

namespace {

std::string where(const std::string& path, std::size_t line) { return path + ":" + std::to_string(line); }

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\r') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool parse_number(const std::string& s, double& v) {
  const char* b = s.data();
  const char* e = b + s.size();
  if (b != e && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, v);
  return ec == std::errc{} && p == e && std::isfinite(v);
}

/// "z[nm]" -> factor to SI of a length unit; names and units checked.
double header_unit(const std::string& field, char name, const std::string& at) {
  const auto open = field.find('[');
  if (field.empty() || std::tolower(static_cast<unsigned char>(field[0])) != name || open != 1 ||
      field.back() != ']')
    throw tools::BadInput(at + ": header field '" + field + "' should read '" + std::string(1, name) +
                          "[UNIT]' with a length unit, e.g. " + name + "[nm]");
  std::string error;
  auto q = inputs::parse_unit(field.substr(open + 1, field.size() - open - 2), &error);
  if (!q) throw tools::BadInput(at + ": " + error);
  if (!(q->dimension == inputs::dim::length))
    throw tools::BadInput(at + ": unit of '" + field + "' is " + q->dimension.str() + ", expected a length (nm, um, m)");
  return q->value;
}

}  // namespace

RawProfile read_profile_file(const std::string& path, std::optional<double> dx) {
  std::ifstream in(path);
  if (!in) throw tools::BadInput(path + ": cannot open the profile file; check the path");
  RawProfile p;
  p.origin = path;
  std::string line;
  std::size_t number = 0, columns = 0;
  double x_unit = 1.0, z_unit = 1.0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++number;
    const auto fields = split_fields(line);
    if (fields.empty() || fields[0][0] == '#') continue;
    const std::string at = where(path, number);
    if (!header_seen && !columns && std::isalpha(static_cast<unsigned char>(fields[0][0]))) {
      header_seen = true;
      if (fields.size() == 2) {
        x_unit = header_unit(fields[0], 'x', at);
        z_unit = header_unit(fields[1], 'z', at);
        columns = 2;
      } else if (fields.size() == 1) {
        z_unit = header_unit(fields[0], 'z', at);
        columns = 1;
      } else {
        throw tools::BadInput(at + ": header has " + std::to_string(fields.size()) +
                              " fields; expected 'x[UNIT],z[UNIT]' or 'z[UNIT]'");
      }
      continue;
    }
    if (!columns) {
      if (fields.size() == 2)
        throw tools::BadInput(at + ": two columns need a header line 'x[UNIT],z[UNIT]' naming their units");
      columns = 1;
    }
    if (fields.size() != columns)
      throw tools::BadInput(at + ": expected " + std::to_string(columns) + " value(s), found " +
                            std::to_string(fields.size()));
    double v[2];
    for (std::size_t c = 0; c < columns; ++c)
      if (!parse_number(fields[c], v[c]))
        throw tools::BadInput(at + ": '" + fields[c] + "' is not a finite number");
    if (columns == 2) {
      const double x = v[0] * x_unit;
      if (!p.x.empty() && !(x > p.x.back()))
        throw tools::BadInput(at + ": x must increase strictly from line to line");
      p.x.push_back(x);
      p.z.push_back(v[1] * z_unit);
    } else {
      p.z.push_back(v[0] * z_unit);
    }
  }
  if (p.z.size() < 3) throw tools::BadInput(path + ": needs at least 3 height values, found " + std::to_string(p.z.size()));
  if (columns == 1) {
    if (!dx || !(*dx > 0.0))
      throw tools::BadInput(path + ": a one-column profile needs the sample spacing: add --dx (e.g. --dx 10nm)");
    for (std::size_t i = 0; i < p.z.size(); ++i) p.x.push_back(*dx * static_cast<double>(i));
  }
  return p;
}

namespace {
/// "…/data/afm/di-1.di" with channel "Height" -> "di-1.di channel Height".
std::string map_name(const mesh::afm::HeightMap& map) {
  const auto slash = map.source.find_last_of('/');
  std::string name = slash == std::string::npos ? map.source : map.source.substr(slash + 1);
  if (!map.channel.empty()) name += " channel " + map.channel;
  return name;
}

/// Row iy (along x) or column ix (along y) of the map, positions from 0.
RawProfile map_line(const mesh::afm::HeightMap& map, bool along_x, std::size_t index) {
  RawProfile p;
  p.origin = map_name(map) + (along_x ? " row " : " column ") + std::to_string(index);
  const std::size_t n = along_x ? map.nx : map.ny;
  for (std::size_t k = 0; k < n; ++k) {
    p.x.push_back((along_x ? map.dx : map.dy) * static_cast<double>(k));
    p.z.push_back(along_x ? map.at(k, index) : map.at(index, k));
  }
  return p;
}
}  // namespace

RawProfile map_row(const mesh::afm::HeightMap& map, std::size_t iy) { return map_line(map, true, iy); }

RawProfile map_column(const mesh::afm::HeightMap& map, std::size_t ix) { return map_line(map, false, ix); }

void check_sample_count(double count, const std::string& what, const std::string& fix) {
  if (count <= kMaxProfileSamples) return;
  char b[64];
  std::snprintf(b, sizeof b, "%.3g samples", count);
  throw tools::BadInput("tribex pstd: " + what + " needs " + b + ", more than the limit of 1e8 samples per profile (0.8 GB "
                        "an array); " + fix);
}

namespace {
std::string um(double length) {
  char b[40];
  std::snprintf(b, sizeof b, "%g um", length * 1e6);
  return b;
}
std::string metres(double length) {
  char b[40];
  std::snprintf(b, sizeof b, "%g m", length);
  return b;
}
}  // namespace

Profile periodic_fine(const RawProfile& raw, double dx) {
  Profile p;
  p.dx = dx;
  p.source_dx = raw.mean_spacing();
  p.origin = raw.origin;
  const double length = raw.x.back() - raw.x.front() + p.source_dx;
  check_sample_count(length / dx, "the substrate (" + um(length) + " at --sampling " + metres(dx) + ")",
                     "choose a coarser --sampling or a shorter substrate");
  const auto n = static_cast<std::size_t>(std::floor(length / dx + 1e-9));
  p.z = resample(raw.x, raw.z, raw.x.front(), dx, n, true);
  return p;
}

Profile window_fine(const RawProfile& raw, double start, double length, double dx, bool levelled) {
  const double spacing = raw.mean_spacing();
  if (start < raw.x.front() || start + length > raw.x.back() + 1e-9 * spacing)
    throw tools::BadInput(raw.origin + ": line is " + std::to_string((raw.x.back() - raw.x.front()) * 1e6) +
                          " um long, too short for a " + std::to_string(length * 1e6) +
                          " um counterface segment; use a shorter --segment-length");
  RawProfile w;
  for (std::size_t i = 0; i < raw.x.size(); ++i) {
    // Keep the samples covering [start, start + length], one beyond each end for the interpolation.
    const bool before_next = i + 1 < raw.x.size() && raw.x[i + 1] <= start;
    const bool after_prev = i > 0 && raw.x[i - 1] >= start + length;
    if (!before_next && !after_prev) { w.x.push_back(raw.x[i]); w.z.push_back(raw.z[i]); }
  }
  if (levelled) level(w.z);
  Profile p;
  p.dx = dx;
  p.source_dx = spacing;
  p.origin = raw.origin;
  check_sample_count(length / dx, "a counterface segment (" + um(length) + " at --sampling " + metres(dx) + ")",
                     "choose a coarser --sampling or a shorter --segment-length");
  const auto n = static_cast<std::size_t>(std::floor(length / dx + 1e-9));
  p.z = resample(w.x, w.z, start, dx, n, false);
  return p;
}

}  // namespace tribex::pstd
