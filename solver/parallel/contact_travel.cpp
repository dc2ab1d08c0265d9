// SPDX-License-Identifier: MIT
#include "solver/parallel/contact_travel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

#include "solver/time_function.hpp"

namespace tribex::solver {
namespace {

// The connected pieces of the mesh: a representative node per node (union-find over each element's
// nodes, path halving).
class Pieces {
 public:
  explicit Pieces(const mesh::Mesh& mesh) : parent_(static_cast<std::size_t>(mesh.node_count())) {
    std::iota(parent_.begin(), parent_.end(), 0);
    for (int e = 0; e < mesh.element_count(); ++e)
      for (int a = 1; a < 8; ++a) join(mesh.connectivity[8 * e], mesh.connectivity[8 * e + a]);
  }
  int root(int n) {
    while (parent_[n] != n) n = parent_[n] = parent_[parent_[n]];
    return n;
  }

 private:
  void join(int a, int b) {
    a = root(a), b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  std::vector<int> parent_;
};

// fn(the 4 nodes of a face) for every face of `surface` (side sets missing from the mesh skipped:
// build_contact reports them).
template <class Fn>
void for_each_face(const mesh::Mesh& mesh, const inputs::ContactSurfaceSpec& surface, Fn&& fn) {
  for (const auto& name : surface.side_sets) {
    const auto it = mesh.side_sets.find(name);
    if (it == mesh.side_sets.end()) continue;
    for (const auto& side : it->second) fn(mesh.side_nodes(side));
  }
}

// The sum of a surface's face area vectors (outward), m^2, and the sum of their magnitudes.
struct AreaSum {
  std::array<double, 3> vector{0, 0, 0};
  double magnitude = 0.0;
};

AreaSum area_sum(const mesh::Mesh& mesh, const inputs::ContactSurfaceSpec& surface) {
  AreaSum sum;
  for_each_face(mesh, surface, [&](const std::array<int, 4>& n) {
    const double* p[4];
    for (int a = 0; a < 4; ++a) p[a] = &mesh.coordinates[3 * static_cast<std::size_t>(n[a])];
    // A quadrilateral's area vector: half the cross product of its diagonals.
    const double d[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double e[3] = {p[3][0] - p[1][0], p[3][1] - p[1][1], p[3][2] - p[1][2]};
    const double a[3] = {0.5 * (d[1] * e[2] - d[2] * e[1]), 0.5 * (d[2] * e[0] - d[0] * e[2]),
                         0.5 * (d[0] * e[1] - d[1] * e[0])};
    for (int i = 0; i < 3; ++i) sum.vector[i] += a[i];
    sum.magnitude += std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  });
  return sum;
}

// The dominant component of the largest summed area vector of the contact surfaces, or -1. A surface
// whose faces sum to under a quarter of their area (a closed or strongly curved one) decides nothing.
int normal_axis(const mesh::Mesh& mesh, const inputs::ContactSpec& contact) {
  int axis = -1;
  double largest = 0.0;
  for (const auto& surface : contact.surfaces) {
    const AreaSum s = area_sum(mesh, surface);
    const double length = std::hypot(s.vector[0], s.vector[1], s.vector[2]);
    if (length <= 0.25 * s.magnitude || length <= largest) continue;
    largest = length;
    axis = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(s.vector[i]) > std::abs(s.vector[axis])) axis = i;
  }
  return axis;
}

// The distance a prescribed motion covers from t0 to t1, m: the total variation of the displacement
// scale * f(t), or the integral of |scale * v(t)| (exact for the piecewise-linear table: a segment
// whose velocity changes sign is split at its zero).
double motion_distance(const inputs::PrescribedMotionSpec& motion, const inputs::FunctionSpec& spec, double t0, double t1) {
  const TimeFunction f(spec);
  std::vector<double> times{t0};
  for (double t : spec.abscissa)
    if (t > t0 && t < t1) times.push_back(t);
  times.push_back(t1);
  double distance = 0.0;
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const double a = motion.scale_factor * f(times[k]), b = motion.scale_factor * f(times[k + 1]);
    const double dt = times[k + 1] - times[k];
    if (motion.kind == inputs::PrescribedMotionSpec::Kind::displacement)
      distance += std::abs(b - a);
    else if (a * b >= 0.0)
      distance += 0.5 * std::abs(a + b) * dt;
    else
      distance += 0.5 * dt * (a * a + b * b) / (std::abs(a) + std::abs(b));
  }
  return distance;
}

// The smallest extent along `axis` of the contact surfaces' face nodes, m (surfaces without faces
// skipped).
double smallest_extent(const mesh::Mesh& mesh, const inputs::ContactSpec& contact, int axis) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& surface : contact.surfaces) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for_each_face(mesh, surface, [&](const std::array<int, 4>& nodes) {
      for (int n : nodes) {
        const double x = mesh.coordinates[3 * static_cast<std::size_t>(n) + static_cast<std::size_t>(axis)];
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    });
    if (hi >= lo) smallest = std::min(smallest, hi - lo);
  }
  return smallest;
}

}  // namespace

namespace {

// contact_travel on `mesh` (whose side sets hold the contact surfaces' faces), the connected pieces given
// by `face_piece` (a face node's piece, in [0, pieces)) and `set_pieces` (the pieces of a node set's
// nodes; none: no such set).
std::optional<ContactTravel> travel_of(const inputs::Deck& deck, const mesh::Mesh& mesh, int pieces,
                                       const std::function<int(int)>& face_piece,
                                       const std::function<std::optional<std::vector<int>>(const std::string&)>& set_pieces) {
  const auto& region = deck.procedure.region;
  std::vector<char> contact_piece(static_cast<std::size_t>(pieces), 0);
  for (const auto& surface : region.contact->surfaces)
    for_each_face(mesh, surface, [&](const std::array<int, 4>& n) { contact_piece[face_piece(n[0])] = 1; });
  const int normal = normal_axis(mesh, *region.contact);
  const auto& time = deck.procedure.time_control;
  std::optional<ContactTravel> travel;
  for (const auto& motion : region.prescribed_motions) {
    const int axis = static_cast<int>(motion.component);
    const inputs::FunctionSpec* function = deck.find_function(motion.function);
    if (axis == normal || !function) continue;
    const auto set = set_pieces(motion.node_set);
    if (!set) continue;
    const bool moves_contact_body = std::any_of(set->begin(), set->end(), [&](int p) { return contact_piece[p] != 0; });
    if (!moves_contact_body) continue;
    const double distance = motion_distance(motion, *function, time.start_time, time.termination_time);
    if (distance > 0.0 && (!travel || distance > travel->distance))
      travel = ContactTravel{axis, distance, motion.node_set, normal};
  }
  if (travel) travel->zone_extent = smallest_extent(mesh, *region.contact, travel->axis);
  return travel;
}

}  // namespace

std::optional<ContactTravel> contact_travel(const inputs::Deck& deck, const mesh::Mesh& mesh) {
  const auto& region = deck.procedure.region;
  if (!region.contact || region.prescribed_motions.empty()) return std::nullopt;
  Pieces pieces(mesh);
  return travel_of(deck, mesh, mesh.node_count(), [&](int n) { return pieces.root(n); },
                   [&](const std::string& name) -> std::optional<std::vector<int>> {
                     const auto set = mesh.node_sets.find(name);
                     if (set == mesh.node_sets.end()) return std::nullopt;
                     std::vector<int> roots;
                     for (int n : set->second) roots.push_back(pieces.root(n));
                     return roots;
                   });
}

std::optional<ContactTravel> contact_travel(const inputs::Deck& deck, const mesh::GeneratedPlan& plan) {
  const auto& region = deck.procedure.region;
  if (!region.contact || region.prescribed_motions.empty()) return std::nullopt;
  // A generated mesh's connected pieces are its grids (append never merges nodes; a grid is connected).
  std::vector<int> elements, global_node;
  for (const auto& surface : region.contact->surfaces)
    for (const auto& name : surface.side_sets)
      if (const auto it = plan.side_sets.find(name); it != plan.side_sets.end())
        for (const auto& side : it->second) elements.push_back(side.element);
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  const mesh::Mesh surfaces = mesh::generate_elements(plan, elements, global_node);
  return travel_of(deck, surfaces, static_cast<int>(plan.grids.size()),
                   [&](int n) { return mesh::grid_of_node(plan, global_node[static_cast<std::size_t>(n)]); },
                   [&](const std::string& name) -> std::optional<std::vector<int>> {
                     std::vector<int> grids;
                     if (const auto set = plan.node_sets.find(name); set != plan.node_sets.end()) {
                       for (int n : set->second) grids.push_back(mesh::grid_of_node(plan, n));
                     } else if (const auto range = plan.node_set_ranges.find(name); range != plan.node_set_ranges.end()) {
                       if ((*range).second[1] > (*range).second[0]) grids.push_back(mesh::grid_of_node(plan, (*range).second[0]));
                     } else {
                       return std::nullopt;
                     }
                     return grids;
                   });
}

std::optional<ContactTravel> contact_travel_one_piece(const inputs::Deck& deck, const mesh::Mesh& surfaces,
                                                      const std::vector<std::string>& node_sets) {
  const auto& region = deck.procedure.region;
  if (!region.contact || region.prescribed_motions.empty()) return std::nullopt;
  return travel_of(deck, surfaces, 1, [](int) { return 0; },
                   [&](const std::string& name) -> std::optional<std::vector<int>> {
                     if (std::find(node_sets.begin(), node_sets.end(), name) == node_sets.end()) return std::nullopt;
                     return std::vector<int>{0};
                   });
}

bool crosses_patches(const ContactTravel& travel, int parts) {
  return travel.distance * parts > travel.zone_extent;
}

parallel::AxisScale decomposition_scale(const inputs::DecompositionSpec& spec, const std::optional<ContactTravel>& travel,
                                        int parts) {
  if (spec.coordinate_scale) return *spec.coordinate_scale;
  parallel::AxisScale scale = parallel::kUnitScale;
  if (travel && crosses_patches(*travel, parts)) scale[travel->axis] = kTravelScale;
  return scale;
}

}  // namespace tribex::solver
