// SPDX-License-Identifier: MIT
#include "tools/pstd/profile_sources.hpp"

#include <charconv>
#include <cmath>
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

RawProfile HeightMap::row(std::size_t r) const {
  RawProfile p;
  p.origin = origin + " row " + std::to_string(r);
  for (std::size_t c = 0; c < nx; ++c) {
    p.x.push_back(dx * static_cast<double>(c));
    p.z.push_back(z[r * nx + c]);
  }
  return p;
}

RawProfile HeightMap::column(std::size_t c) const {
  RawProfile p;
  p.origin = origin + " column " + std::to_string(c);
  for (std::size_t r = 0; r < ny; ++r) {
    p.x.push_back(dy * static_cast<double>(r));
    p.z.push_back(z[r * nx + c]);
  }
  return p;
}

HeightMap read_height_map(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw tools::BadInput(path + ": cannot open the height map; check the path");
  HeightMap map;
  map.origin = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  double width = 0.0, height = 0.0, z_unit = 0.0;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string at = where(path, number);
    if (!line.empty() && line[0] == '#') {
      const auto colon = line.find(':');
      if (colon == std::string::npos) continue;
      std::string key = line.substr(1, colon - 1);
      while (!key.empty() && key.front() == ' ') key.erase(key.begin());
      const std::string value = line.substr(colon + 1);
      std::string error;
      if (key == "Width" || key == "Height") {
        auto q = inputs::parse_quantity(value, &error);
        if (!q || !(q->dimension == inputs::dim::length) || !(q->value > 0))
          throw tools::BadInput(at + ": '" + key + ":' needs a positive length like '10.00 µm'" +
                                (error.empty() ? "" : " (" + error + ")"));
        (key == "Width" ? width : height) = q->value;
      } else if (key == "Value units") {
        std::string u = value;
        while (!u.empty() && u.front() == ' ') u.erase(u.begin());
        auto q = inputs::parse_unit(u, &error);
        if (!q || !(q->dimension == inputs::dim::length))
          throw tools::BadInput(at + ": 'Value units:' must be a length unit (m, nm), got '" + u + "'");
        z_unit = q->value;
      }
      continue;
    }
    const auto fields = split_fields(line);
    if (fields.empty()) continue;
    if (width <= 0 || height <= 0 || z_unit <= 0)
      throw tools::BadInput(at + ": not a Gwyddion ASCII matrix (data before the '# Width:', '# Height:' and "
                            "'# Value units:' header lines); --afm reads only that format for now: export a line "
                            "as x[nm],z[nm] CSV and use --substrate-file");
    if (map.nx == 0) map.nx = fields.size();
    if (fields.size() != map.nx)
      throw tools::BadInput(at + ": row has " + std::to_string(fields.size()) + " values, the first row had " +
                            std::to_string(map.nx) + "; the matrix must be rectangular");
    for (const auto& f : fields) {
      double v = 0.0;
      if (!parse_number(f, v)) throw tools::BadInput(at + ": '" + f + "' is not a finite number");
      map.z.push_back(v * (z_unit > 0 ? z_unit : 1.0));
    }
    ++map.ny;
  }
  if (width <= 0 || height <= 0 || z_unit <= 0)
    throw tools::BadInput(path + ": not a Gwyddion ASCII matrix: the header needs '# Width:', '# Height:' and "
                          "'# Value units:' lines (other AFM formats: export a line as x[nm],z[nm] CSV)");
  if (map.nx < 3 || map.ny < 3) throw tools::BadInput(path + ": height map smaller than 3 x 3");
  map.dx = width / static_cast<double>(map.nx);
  map.dy = height / static_cast<double>(map.ny);
  return map;
}

Profile periodic_fine(const RawProfile& raw, double dx) {
  Profile p;
  p.dx = dx;
  p.source_dx = raw.mean_spacing();
  p.origin = raw.origin;
  const double length = raw.x.back() - raw.x.front() + p.source_dx;
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
  const auto n = static_cast<std::size_t>(std::floor(length / dx + 1e-9));
  p.z = resample(w.x, w.z, start, dx, n, false);
  return p;
}

}  // namespace tribex::pstd
