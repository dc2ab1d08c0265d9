// SPDX-License-Identifier: MIT
#include "mesh/vertical_gap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {

namespace {

struct Triangle {
  std::array<double, 9> x;  // 3 corners, x y z each
};

/// The triangles of a side set, bucketed on a uniform x-y grid so that a point meets only the few
/// triangles whose bounding box covers its cell.
class HeightField {
 public:
  HeightField(const Mesh& mesh, const std::vector<Side>& sides) {
    const double* c = mesh.coordinates.data();
    for (const Side& s : sides) {
      const auto n = mesh.side_nodes(s);
      for (const auto& corner : {std::array<int, 3>{n[0], n[1], n[2]}, std::array<int, 3>{n[0], n[2], n[3]}}) {
        Triangle t;
        for (int k = 0; k < 3; ++k)
          for (int d = 0; d < 3; ++d) t.x[3 * k + d] = c[3 * corner[k] + d];
        triangles_.push_back(t);
      }
    }
    if (triangles_.empty()) return;
    lo_ = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    auto& hi = hi_;
    hi = {-lo_[0], -lo_[1]};
    for (const Triangle& t : triangles_)
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 2; ++d) {
          lo_[d] = std::min(lo_[d], t.x[3 * k + d]);
          hi[d] = std::max(hi[d], t.x[3 * k + d]);
        }
    // About two triangles per cell on average.
    const double area = std::max((hi[0] - lo_[0]) * (hi[1] - lo_[1]), 1e-300);
    cell_ = std::max(std::sqrt(2.0 * area / static_cast<double>(triangles_.size())), 1e-300);
    for (int d = 0; d < 2; ++d) cells_[d] = std::max(1, static_cast<int>(std::ceil((hi[d] - lo_[d]) / cell_)));
    buckets_.resize(static_cast<std::size_t>(cells_[0]) * cells_[1]);
    for (std::size_t i = 0; i < triangles_.size(); ++i) {
      const auto& x = triangles_[i].x;
      const int i0 = cell(std::min({x[0], x[3], x[6]}), 0), i1 = cell(std::max({x[0], x[3], x[6]}), 0);
      const int j0 = cell(std::min({x[1], x[4], x[7]}), 1), j1 = cell(std::max({x[1], x[4], x[7]}), 1);
      for (int j = j0; j <= j1; ++j)
        for (int k = i0; k <= i1; ++k) buckets_[static_cast<std::size_t>(j) * cells_[0] + k].push_back(i);
    }
  }

  /// Height of the surface at (x, y), or nullopt off it. Where triangles overlap in plan view (a
  /// fold), the highest is taken for a lower surface and the lowest for an upper one.
  std::optional<double> height(double x, double y, bool take_highest) const {
    if (triangles_.empty() || x < lo_[0] || y < lo_[1] || x > hi_[0] || y > hi_[1]) return std::nullopt;
    const int i = cell(x, 0), j = cell(y, 1);
    std::optional<double> z;
    constexpr double tol = 1e-12;  // barycentric slack: a node on a shared edge finds either triangle
    for (std::size_t t : buckets_[static_cast<std::size_t>(j) * cells_[0] + i]) {
      const auto& p = triangles_[t].x;
      const double det = (p[3] - p[0]) * (p[7] - p[1]) - (p[6] - p[0]) * (p[4] - p[1]);
      if (std::abs(det) <= 0.0) continue;  // vertical in plan view: no height
      const double b1 = ((x - p[0]) * (p[7] - p[1]) - (p[6] - p[0]) * (y - p[1])) / det;
      const double b2 = ((p[3] - p[0]) * (y - p[1]) - (x - p[0]) * (p[4] - p[1])) / det;
      if (b1 < -tol || b2 < -tol || b1 + b2 > 1 + tol) continue;
      const double h = p[2] + b1 * (p[5] - p[2]) + b2 * (p[8] - p[2]);
      z = !z ? h : take_highest ? std::max(*z, h) : std::min(*z, h);
    }
    return z;
  }

 private:
  int cell(double v, int d) const {
    return std::clamp(static_cast<int>(std::floor((v - lo_[d]) / cell_)), 0, cells_[d] - 1);
  }
  std::vector<Triangle> triangles_;
  std::array<double, 2> lo_{}, hi_{};
  double cell_ = 1.0;
  std::array<int, 2> cells_{1, 1};
  std::vector<std::vector<std::size_t>> buckets_;
};

const std::vector<Side>& side_set(const Mesh& mesh, const std::string& name) {
  const auto it = mesh.side_sets.find(name);
  if (it == mesh.side_sets.end()) throw MeshError("the mesh has no side set '" + name + "'");
  return it->second;
}

}  // namespace

std::optional<double> smallest_vertical_gap(const Mesh& mesh, const std::string& upper, const std::string& lower) {
  const HeightField up(mesh, side_set(mesh, upper)), down(mesh, side_set(mesh, lower));
  std::optional<double> gap;
  const auto consider = [&](double g) { gap = gap ? std::min(*gap, g) : g; };
  const double* c = mesh.coordinates.data();
  for (int n : mesh.side_set_nodes(upper))
    if (auto h = down.height(c[3 * n], c[3 * n + 1], true)) consider(c[3 * n + 2] - *h);
  for (int n : mesh.side_set_nodes(lower))
    if (auto h = up.height(c[3 * n], c[3 * n + 1], false)) consider(*h - c[3 * n + 2]);
  return gap;
}

}  // namespace tribex::mesh
