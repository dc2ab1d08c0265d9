// SPDX-License-Identifier: MIT
// Gwyddion ASCII matrix export reader.
// Header lines "# Channel: NAME", "# Width: 10.00 µm", "# Height: 10.00 µm", "# Value units: m";
// then one text row per scan line (row = y, column = x), numbers separated by tabs or blanks.
#include <cmath>

#include "mesh/afm/height_map.hpp"
#include "mesh/afm/text_util.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {

HeightMap read_gwyddion_matrix(const std::string& path) {
  using namespace detail;
  const std::string text = read_file_bytes(path);
  HeightMap m;
  m.source = path;
  m.channel = "matrix";
  double width = -1.0, height = -1.0, zunit = 1.0;
  std::size_t row_len = 0;
  auto header = [&](const TextLine& line) {
    const auto colon = line.text.find(':');
    if (colon == std::string::npos) return;
    const std::string key = trim(line.text.substr(1, colon - 1));
    const std::string value = trim(line.text.substr(colon + 1));
    if (key == "Channel") m.channel = value;
    if (key == "Width" || key == "Height") {
      const auto f = split_fields(value);
      auto v = f.size() == 2 ? to_number(f[0]) : std::nullopt;
      auto u = f.size() == 2 ? metres_per(f[1]) : std::nullopt;
      if (!v || !u || !(*v > 0.0))
        throw MeshError(line.where + ": expected '# " + key + ": VALUE UNIT' with a positive value and a length unit, got '" +
                        value + "'");
      (key == "Width" ? width : height) = *v * *u;
    }
    if (key == "Value units") {
      auto u = metres_per(value);
      if (!u) throw MeshError(line.where + ": value units '" + value + "' are not a length (m, um, nm, pm); not a height map");
      zunit = *u;
    }
  };
  auto row = [&](const TextLine& line) {
    const auto fields = split_fields(line.text);
    if (row_len == 0) row_len = fields.size();
    if (fields.size() != row_len)
      throw MeshError(line.where + ": expected " + std::to_string(row_len) + " values like the first data row, got " +
                      std::to_string(fields.size()) + " (truncated or ragged matrix)");
    for (std::size_t i = 0; i < fields.size(); ++i) m.heights.push_back(finite_field(fields, i, line.where) * zunit);
    ++m.ny;
  };
  const int line_no = for_each_line(text, path, header, row);
  m.nx = row_len;
  if (width <= 0.0 || height <= 0.0)
    throw MeshError(path + ":1: expected '# Width:' and '# Height:' header lines giving the physical size");
  if (m.nx == 0) throw MeshError(path + ":" + std::to_string(line_no) + ": expected rows of heights after the header, found none");
  m.dx = width / static_cast<double>(m.nx);
  m.dy = height / static_cast<double>(m.ny);
  check_height_map(m, path);
  return m;
}

}  // namespace tribex::mesh::afm
