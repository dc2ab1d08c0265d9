// SPDX-License-Identifier: MIT
// Plain XYZ text reader: "x y z" per line (blanks, tabs or commas) on a regular, complete grid.
// Lines starting with '#' are comments; "# units: nm" (m, mm, um, nm, pm) scales all three columns,
// otherwise SI metres. Points may come in any order; the grid is rebuilt from the distinct x and y.
#include <algorithm>
#include <cmath>
#include <map>

#include "mesh/afm/height_map.hpp"
#include "mesh/afm/text_util.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {

HeightMap read_xyz_text(const std::string& path) {
  using namespace detail;
  const std::string text = read_file_bytes(path);
  struct P { double x, y, z; int line; };
  std::vector<P> pts;
  double unit = 1.0;
  auto units = [&](const TextLine& line) {
    const auto k = line.text.find("units:");
    if (k == std::string::npos) return;
    auto u = metres_per(line.text.substr(k + 6));
    if (!u) throw MeshError(line.where + ": unknown length unit in '" + line.text + "' (use m, mm, um, nm or pm)");
    unit = *u;
  };
  auto point = [&](const TextLine& line) {
    const auto f = split_fields(line.text, true);
    if (f.size() != 3)
      throw MeshError(line.where + ": expected 3 columns 'x y z', got " + std::to_string(f.size()) +
                      " (is this really an XYZ text file?)");
    pts.push_back({finite_field(f, 0, line.where) * unit, finite_field(f, 1, line.where) * unit,
                   finite_field(f, 2, line.where) * unit, line.number});
  };
  for_each_line(text, path, units, point);
  if (pts.size() < 4) throw MeshError(path + ": expected at least 4 'x y z' points (a 2 x 2 grid), got " + std::to_string(pts.size()));
  // Distinct coordinates with a tolerance relative to the extent (text rounding).
  auto distinct = [](std::vector<double> c) {
    std::sort(c.begin(), c.end());
    const double tol = 1e-6 * std::max(1e-300, c.back() - c.front());
    std::vector<double> out{c.front()};
    for (double x : c) if (x - out.back() > tol) out.push_back(x);
    return out;
  };
  std::vector<double> xs, ys;
  for (const auto& p : pts) { xs.push_back(p.x); ys.push_back(p.y); }
  xs = distinct(xs);
  ys = distinct(ys);
  HeightMap m;
  m.nx = xs.size();
  m.ny = ys.size();
  m.source = path;
  m.channel = "xyz";
  if (m.nx < 2 || m.ny < 2 || m.nx * m.ny != pts.size())
    throw MeshError(path + ": expected a complete regular grid, got " + std::to_string(pts.size()) + " points on " +
                    std::to_string(m.nx) + " distinct x and " + std::to_string(m.ny) + " distinct y (missing or duplicate points)");
  m.dx = (xs.back() - xs.front()) / static_cast<double>(m.nx - 1);
  m.dy = (ys.back() - ys.front()) / static_cast<double>(m.ny - 1);
  for (std::size_t i = 1; i < m.nx; ++i)
    if (std::fabs(xs[i] - xs[i - 1] - m.dx) > 1e-3 * m.dx)
      throw MeshError(path + ": x values are not evenly spaced near x = " + std::to_string(xs[i]) + " m (expected step " + std::to_string(m.dx) + " m)");
  for (std::size_t i = 1; i < m.ny; ++i)
    if (std::fabs(ys[i] - ys[i - 1] - m.dy) > 1e-3 * m.dy)
      throw MeshError(path + ": y values are not evenly spaced near y = " + std::to_string(ys[i]) + " m (expected step " + std::to_string(m.dy) + " m)");
  m.heights.assign(m.nx * m.ny, std::nan(""));
  for (const auto& p : pts) {
    const auto ix = static_cast<std::size_t>(std::lround((p.x - xs.front()) / m.dx));
    const auto iy = static_cast<std::size_t>(std::lround((p.y - ys.front()) / m.dy));
    if (ix >= m.nx || iy >= m.ny) throw MeshError(path + ":" + std::to_string(p.line) + ": point lies off the regular grid");
    double& h = m.heights[iy * m.nx + ix];
    if (!std::isnan(h)) throw MeshError(path + ":" + std::to_string(p.line) + ": duplicate grid point (x, y) already given");
    h = p.z;
  }
  check_height_map(m, path);
  return m;
}

}  // namespace tribex::mesh::afm
