// SPDX-License-Identifier: MIT
#include "solver/contact_partition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace tribex::solver {
namespace {

struct SurfaceFaces {
  std::vector<int> element;    // [face]
  std::vector<double> centre;  // [face][3], m
  std::vector<double> size;    // [face] largest diagonal, m
  double mean_size = 0.0;
};

SurfaceFaces faces_of(const mesh::Mesh& mesh, const inputs::ContactSpec& spec, const std::string& surface) {
  SurfaceFaces out;
  for (const auto& s : spec.surfaces) {
    if (s.name != surface) continue;
    for (const auto& set : s.side_sets) {
      const auto it = mesh.side_sets.find(set);
      if (it == mesh.side_sets.end()) continue;
      for (const auto& side : it->second) {
        const auto n = mesh.side_nodes(side);
        const double* p[4];
        for (int a = 0; a < 4; ++a) p[a] = &mesh.coordinates[3 * static_cast<std::size_t>(n[a])];
        double d02 = 0.0, d13 = 0.0;
        for (int i = 0; i < 3; ++i) {
          out.centre.push_back(0.25 * (p[0][i] + p[1][i] + p[2][i] + p[3][i]));
          d02 += (p[2][i] - p[0][i]) * (p[2][i] - p[0][i]);
          d13 += (p[3][i] - p[1][i]) * (p[3][i] - p[1][i]);
        }
        out.size.push_back(std::sqrt(std::max(d02, d13)));
        out.element.push_back(side.element);
      }
    }
  }
  for (double s : out.size) out.mean_size += s / static_cast<double>(out.size.size());
  return out;
}

// A hash grid of face centres, cells of the mean face size.
class CentreGrid {
 public:
  explicit CentreGrid(const SurfaceFaces& faces) : faces_(faces), cell_(faces.mean_size > 0 ? faces.mean_size : 1.0) {
    for (std::size_t f = 0; f < faces.element.size(); ++f) cells_[key(&faces.centre[3 * f], 0, 0, 0)].push_back(static_cast<int>(f));
  }
  /// The face nearest `p` within `radius`, or -1.
  int nearest(const double* p, double radius) const {
    const int reach = static_cast<int>(std::ceil(radius / cell_));
    int best = -1;
    double best_d2 = radius * radius;
    for (int dz = -reach; dz <= reach; ++dz)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const auto it = cells_.find(key(p, dx, dy, dz));
          if (it == cells_.end()) continue;
          for (int f : it->second) {
            double d2 = 0.0;
            for (int i = 0; i < 3; ++i) d2 += (faces_.centre[3 * f + i] - p[i]) * (faces_.centre[3 * f + i] - p[i]);
            if (d2 <= best_d2 && (best < 0 || d2 < best_d2 || f < best)) {
              best = f;
              best_d2 = d2;
            }
          }
        }
    return best;
  }

 private:
  std::int64_t key(const double* p, int dx, int dy, int dz) const {
    const auto c = [&](int i, int d) { return (static_cast<std::int64_t>(std::floor(p[i] / cell_)) + d) & 0x1FFFFF; };
    return (c(2, dz) << 42) | (c(1, dy) << 21) | c(0, dx);
  }
  const SurfaceFaces& faces_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

// For each face of `from`, a link to the element of the nearest face of `to` within reach.
void link_nearest(const SurfaceFaces& from, const SurfaceFaces& to, std::vector<int>& links) {
  if (from.element.empty() || to.element.empty()) return;
  const CentreGrid grid(to);
  for (std::size_t f = 0; f < from.element.size(); ++f) {
    const int g = grid.nearest(&from.centre[3 * f], 2.0 * std::max(from.size[f], to.mean_size));
    if (g < 0) continue;
    const int a = from.element[f], b = to.element[static_cast<std::size_t>(g)];
    if (a == b) continue;
    links.push_back(std::min(a, b));
    links.push_back(std::max(a, b));
  }
}

}  // namespace

std::vector<std::vector<char>> contact_surface_elements(const mesh::Mesh& mesh, const inputs::ContactSpec* spec) {
  std::vector<std::vector<char>> sets;
  if (!spec) return sets;
  for (const auto& s : spec->surfaces) {
    std::vector<char> marked(static_cast<std::size_t>(mesh.element_count()), 0);
    for (const auto& set : s.side_sets)
      if (auto it = mesh.side_sets.find(set); it != mesh.side_sets.end())
        for (const auto& side : it->second) marked[static_cast<std::size_t>(side.element)] = 1;
    sets.push_back(std::move(marked));
  }
  return sets;
}

std::vector<int> contact_element_links(const mesh::Mesh& mesh, const inputs::ContactSpec* spec) {
  std::vector<int> links;
  if (!spec) return links;
  for (const auto& it : spec->interactions) {
    const SurfaceFaces slave = faces_of(mesh, *spec, it.slave), master = faces_of(mesh, *spec, it.master);
    link_nearest(slave, master, links);
    link_nearest(master, slave, links);
  }
  // Each pair once, ascending.
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(links.size() / 2);
  for (std::size_t k = 0; k < links.size(); k += 2) pairs.emplace_back(links[k], links[k + 1]);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  links.clear();
  for (const auto& [a, b] : pairs) {
    links.push_back(a);
    links.push_back(b);
  }
  return links;
}

}  // namespace tribex::solver
