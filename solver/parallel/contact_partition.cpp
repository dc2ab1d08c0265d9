// SPDX-License-Identifier: MIT
#include "solver/parallel/contact_partition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

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

// For each face of `from`, a link to the element of the nearest face of `to` within reach, as a pair
// (slave side, master side): `from_slave` says which side `from` is.
void link_nearest(const SurfaceFaces& from, const SurfaceFaces& to, bool from_slave, std::vector<std::pair<int, int>>& links) {
  if (from.element.empty() || to.element.empty()) return;
  const CentreGrid grid(to);
  for (std::size_t f = 0; f < from.element.size(); ++f) {
    const int g = grid.nearest(&from.centre[3 * f], 2.0 * std::max(from.size[f], to.mean_size));
    if (g < 0) continue;
    const int a = from.element[f], b = to.element[static_cast<std::size_t>(g)];
    if (a == b) continue;
    links.emplace_back(from_slave ? a : b, from_slave ? b : a);
  }
}

// (slave, master) pairs of every interaction, each once, ascending.
std::vector<std::pair<int, int>> facing_pairs(const mesh::Mesh& mesh, const inputs::ContactSpec& spec) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& it : spec.interactions) {
    const SurfaceFaces slave = faces_of(mesh, spec, it.slave), master = faces_of(mesh, spec, it.master);
    link_nearest(slave, master, true, pairs);
    link_nearest(master, slave, false, pairs);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// Length of the diagonal of the faces' centroid box, its sides multiplied by `scale`.
double scaled_extent(const SurfaceFaces& faces, const parallel::AxisScale& scale) {
  if (faces.element.empty()) return 0.0;
  double lo[3], hi[3], d2 = 0.0;
  for (int i = 0; i < 3; ++i) lo[i] = hi[i] = faces.centre[i];
  for (std::size_t f = 0; f < faces.element.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], faces.centre[3 * f + i]);
      hi[i] = std::max(hi[i], faces.centre[3 * f + i]);
    }
  for (int i = 0; i < 3; ++i) d2 += scale[i] * scale[i] * (hi[i] - lo[i]) * (hi[i] - lo[i]);
  return std::sqrt(d2);
}

// [face][3] the face centroids of the smaller side (after `scale`; ties: the slave) of every interaction.
std::vector<double> footprint_centres(const mesh::Mesh& mesh, const inputs::ContactSpec& spec,
                                      const parallel::AxisScale& scale) {
  std::vector<double> centre;
  for (const auto& it : spec.interactions) {
    const SurfaceFaces slave = faces_of(mesh, spec, it.slave), master = faces_of(mesh, spec, it.master);
    const bool master_smaller = !master.element.empty() && scaled_extent(master, scale) < scaled_extent(slave, scale);
    const SurfaceFaces& smaller = master_smaller ? master : slave;
    centre.insert(centre.end(), smaller.centre.begin(), smaller.centre.end());
  }
  return centre;
}

}  // namespace

std::vector<int> contact_element_links(const mesh::Mesh& mesh, const inputs::ContactSpec* spec) {
  std::vector<int> links;
  if (!spec) return links;
  for (const auto& [a, b] : facing_pairs(mesh, *spec)) {
    links.push_back(a);
    links.push_back(b);
  }
  return links;
}

void place_contact_patches(const mesh::Mesh& mesh, const inputs::ContactSpec* spec, int parts, std::vector<int>& part,
                           const parallel::AxisScale& scale) {
  if (!spec || parts <= 1) return;
  // The slave-side elements, ascending, and their face centroids (an element with several slave
  // faces: their mean); arrays by slave element, not by mesh element (rank 0 runs this on the whole mesh).
  std::vector<std::pair<int, std::array<double, 3>>> faces;  // (element, face centroid)
  for (const auto& it : spec->interactions)
    for (const std::string* name : {&it.slave, it.symmetric ? &it.master : nullptr}) {
      if (!name) continue;
      const SurfaceFaces f = faces_of(mesh, *spec, *name);
      for (std::size_t k = 0; k < f.element.size(); ++k)
        faces.push_back({f.element[k], {f.centre[3 * k], f.centre[3 * k + 1], f.centre[3 * k + 2]}});
    }
  if (faces.empty()) return;
  std::sort(faces.begin(), faces.end());
  std::vector<int> slave;
  std::vector<double> centre;
  for (std::size_t k = 0; k < faces.size();) {
    std::size_t end = k;
    double c[3] = {0, 0, 0};
    for (; end < faces.size() && faces[end].first == faces[k].first; ++end)
      for (int i = 0; i < 3; ++i) c[i] += faces[end].second[i];
    slave.push_back(faces[k].first);
    for (int i = 0; i < 3; ++i) centre.push_back(c[i] / static_cast<double>(end - k));
    k = end;
  }
  faces = {};
  // The cuts come from the smaller surface of each interaction (its footprint holds the contact zone):
  // on a track swept by a tip, the planes through the tip share the zone evenly, where the track's own
  // median would follow its coarse faces away from the tip.
  const std::vector<double> footprint = footprint_centres(mesh, *spec, scale);
  const int count = static_cast<int>(slave.size());
  const int references = static_cast<int>(footprint.size() / 3);
  const int patches = std::min({parts, count, references});
  if (patches < 1) return;
  std::vector<int> patch_of(slave.size(), -1), items(slave.size()), reference(static_cast<std::size_t>(references));
  std::iota(items.begin(), items.end(), 0);
  std::iota(reference.begin(), reference.end(), 0);
  parallel::bisect_like(reference, 0, reference.size(), footprint, items, 0, items.size(), centre, 0, patches,
                        patch_of, scale);
  // Patch -> rank: largest overlap with the METIS parts first (ties: lower patch, then lower rank).
  std::vector<long long> overlap(static_cast<std::size_t>(patches) * parts, 0);
  for (int k = 0; k < count; ++k) ++overlap[static_cast<std::size_t>(patch_of[k]) * parts + part[slave[k]]];
  std::vector<std::pair<long long, int>> order;  // (-count, patch * parts + rank)
  for (std::size_t k = 0; k < overlap.size(); ++k) order.emplace_back(-overlap[k], static_cast<int>(k));
  std::sort(order.begin(), order.end());
  std::vector<int> rank_of_patch(static_cast<std::size_t>(patches), -1);
  std::vector<char> taken(static_cast<std::size_t>(parts), 0);
  for (const auto& entry : order) {
    const int p = entry.second / parts, r = entry.second % parts;
    if (rank_of_patch[p] < 0 && !taken[r]) {
      rank_of_patch[p] = r;
      taken[r] = 1;
    }
  }
  for (int k = 0; k < count; ++k) part[slave[k]] = rank_of_patch[patch_of[k]];
  // Master elements facing a slave face go with it (the first pair of each master element; not a
  // slave element itself).
  std::vector<char> placed(static_cast<std::size_t>(mesh.element_count()), 0);
  for (int e : slave) placed[e] = 1;
  for (const auto& [s, m] : facing_pairs(mesh, *spec))
    if (!placed[m]) {
      part[m] = part[s];
      placed[m] = 1;
    }
}

}  // namespace tribex::solver
