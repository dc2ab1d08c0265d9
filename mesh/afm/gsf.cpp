// SPDX-License-Identifier: MIT
// Gwyddion Simple Field 1.0 reader.
// Layout: magic line "Gwyddion Simple Field 1.0\n", "Name = Value\n" lines, 1-4 NUL bytes so that the
// data start at a multiple of 4, then XRes*YRes float32 little-endian values, row by row (row = y).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>

#include "mesh/afm/height_map.hpp"
#include "mesh/afm/text_util.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {

HeightMap read_gsf(const std::string& path) {
  using namespace detail;
  const std::string bytes = read_file_bytes(path);
  const std::string magic = "Gwyddion Simple Field 1.0\n";
  if (bytes.compare(0, magic.size(), magic) != 0)
    throw MeshError(path + ":1:1: expected the magic line 'Gwyddion Simple Field 1.0' (not a GSF file)");
  const std::size_t nul = bytes.find('\0');
  if (nul == std::string::npos)
    throw MeshError(path + ": byte " + std::to_string(bytes.size()) +
                    ": expected NUL padding after the text header (the file is truncated in its header)");
  std::map<std::string, std::pair<std::string, std::size_t>> keys;
  std::size_t pos = magic.size();
  int line_no = 2;
  while (pos < nul) {
    std::size_t eol = bytes.find('\n', pos);
    if (eol == std::string::npos || eol > nul) eol = nul;
    const std::string line = trim(bytes.substr(pos, eol - pos));
    if (!line.empty()) {
      const auto eq = line.find('=');
      if (eq == std::string::npos)
        throw MeshError(path + ":" + std::to_string(line_no) + ": expected 'Name = Value', got '" + line.substr(0, 60) + "'");
      keys[trim(line.substr(0, eq))] = {trim(line.substr(eq + 1)), static_cast<std::size_t>(line_no)};
    }
    pos = eol + 1;
    ++line_no;
  }
  auto get = [&](const std::string& k) -> std::pair<std::string, std::size_t> {
    auto it = keys.find(k);
    if (it == keys.end()) throw MeshError(path + ": header lacks the required key '" + k + "' (GSF needs XRes, YRes)");
    return it->second;
  };
  auto positive_int = [&](const std::string& k) {
    auto [v, ln] = get(k);
    auto n = to_number(v);
    if (!n || *n != std::floor(*n) || *n < 1 || *n > 65536)
      throw MeshError(path + ":" + std::to_string(ln) + ": " + k + " = '" + v + "' must be an integer in [1, 65536]");
    return static_cast<std::size_t>(*n);
  };
  auto real_or = [&](const std::string& k, double fallback) {
    auto it = keys.find(k);
    if (it == keys.end()) return fallback;
    auto n = to_number(it->second.first);
    if (!n || !std::isfinite(*n))
      throw MeshError(path + ":" + std::to_string(it->second.second) + ": " + k + " = '" + it->second.first +
                      "' is not a finite number");
    return *n;
  };
  auto unit = [&](const std::string& k) {
    auto it = keys.find(k);
    if (it == keys.end()) return 1.0;  // GSF default units are metres
    auto m = metres_per(it->second.first);
    if (!m)
      throw MeshError(path + ":" + std::to_string(it->second.second) + ": " + k + " = '" + it->second.first +
                      "' is not a length unit (m, mm, um, nm, pm)");
    return *m;
  };
  HeightMap m;
  m.nx = positive_int("XRes");
  m.ny = positive_int("YRes");
  const double xy = unit("XYUnits"), zu = unit("ZUnits");
  const double xreal = real_or("XReal", 1.0) * xy, yreal = real_or("YReal", 1.0) * xy;
  if (!(xreal > 0.0) || !(yreal > 0.0) || xreal > 1.0 || yreal > 1.0)
    throw MeshError(path + ": XReal and YReal must be positive and at most 1 m, got " + std::to_string(xreal) + " m, " +
                    std::to_string(yreal) + " m");
  m.dx = xreal / static_cast<double>(m.nx);
  m.dy = yreal / static_cast<double>(m.ny);
  // Padding: 1-4 NULs so that the data start at a multiple of 4 (4 NULs when the text is already aligned).
  const std::size_t start = (nul / 4 + 1) * 4;
  for (std::size_t i = nul; i < start && i < bytes.size(); ++i) {
    if (bytes[i] != '\0')
      throw MeshError(path + ": byte " + std::to_string(i) + ": expected NUL padding up to byte " + std::to_string(start));
  }
  const std::size_t n = m.nx * m.ny;
  if (bytes.size() != start + 4 * n)
    throw MeshError(path + ": byte " + std::to_string(bytes.size()) + ": expected exactly " + std::to_string(start + 4 * n) +
                    " bytes (" + std::to_string(m.nx) + " x " + std::to_string(m.ny) + " float32 from byte " +
                    std::to_string(start) + "); the file is truncated or XRes/YRes are wrong");
  m.heights.resize(n);
  const unsigned char* d = reinterpret_cast<const unsigned char*>(bytes.data()) + start;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t u = static_cast<std::uint32_t>(d[4 * i]) | (static_cast<std::uint32_t>(d[4 * i + 1]) << 8) |
                            (static_cast<std::uint32_t>(d[4 * i + 2]) << 16) | (static_cast<std::uint32_t>(d[4 * i + 3]) << 24);
    float f;
    std::memcpy(&f, &u, sizeof f);
    if (!std::isfinite(f))
      throw MeshError(path + ": byte " + std::to_string(start + 4 * i) + ": height value is NaN or Inf");
    m.heights[i] = static_cast<double>(f) * zu;
  }
  auto title = keys.find("Title");
  m.channel = title == keys.end() ? "gsf" : title->second.first;
  m.source = path;
  check_height_map(m, path);
  return m;
}

}  // namespace tribex::mesh::afm
