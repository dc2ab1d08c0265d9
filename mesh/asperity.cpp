// SPDX-License-Identifier: MIT
#include "mesh/asperity.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "mesh/asperity_limits.hpp"
#include "mesh/box.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

// Symmetric axis: fine spacing on [-fine, fine], graded outward to +-half.
std::vector<double> symmetric_axis(double half, double h, double fine, double ratio) {
  const std::vector<double> right = graded_axis(0.0, half, h, fine, ratio);
  std::vector<double> axis;
  for (auto it = right.rbegin(); it != right.rend(); ++it) axis.push_back(-*it);
  axis.insert(axis.end(), right.begin() + 1, right.end());
  return axis;
}

void rename(Mesh& m, const std::string& from, const std::string& to) {
  if (auto it = m.side_sets.find(from); it != m.side_sets.end()) {
    m.side_sets[to] = std::move(it->second);
    m.side_sets.erase(it);
  }
  if (auto it = m.node_sets.find(from); it != m.node_sets.end()) {
    m.node_sets[to] = std::move(it->second);
    m.node_sets.erase(it);
  }
}

void merge_sides(Mesh& m, const std::string& prefix, const std::string& to, bool quarter) {
  std::vector<Side> sides;
  std::vector<int> nodes;
  const std::vector<std::string> faces =
      quarter ? std::vector<std::string>{"_xmax", "_ymax"} : std::vector<std::string>{"_xmin", "_xmax", "_ymin", "_ymax"};
  for (const std::string& f : faces) {
    const auto& s = m.side_sets.at(prefix + f);
    sides.insert(sides.end(), s.begin(), s.end());
    const auto& n = m.node_sets.at(prefix + f);
    nodes.insert(nodes.end(), n.begin(), n.end());
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  m.side_sets[to] = std::move(sides);
  m.node_sets[to] = std::move(nodes);
}

// The first node of `set` (ascending) nearest to (x, y) in plan view; `xy` gives a node's x and y.
int nearest_node(const std::function<std::array<double, 2>(int)>& xy, const std::vector<int>& set, double x, double y) {
  int best = set.front();
  double best_d = INFINITY;
  for (int n : set) {
    const std::array<double, 2> p = xy(n);
    const double d = std::hypot(p[0] - x, p[1] - y);
    if (d < best_d) {
      best_d = d;
      best = n;
    }
  }
  return best;
}

// The lateral axis: symmetric about 0, or (quarter model) from 0 to +half.
std::vector<double> lateral_axis(double half, double h, double fine, double ratio, bool quarter) {
  return quarter ? graded_axis(0.0, half, h, fine, ratio) : symmetric_axis(half, h, fine, ratio);
}

// The substrate's x axis with the fine region [X0, X1] (X0 <= 0 <= X1): fine spacing over it, graded
// outward to +-half; a quarter model keeps x >= 0.
std::vector<double> fine_range_axis(double half, double h, const std::array<double, 2>& range, double ratio, bool quarter) {
  const std::vector<double> right = graded_axis(0.0, half, h, range[1], ratio);
  if (quarter) return right;
  const std::vector<double> left = graded_axis(0.0, half, h, -range[0], ratio);
  std::vector<double> axis;
  for (auto it = left.rbegin(); it != left.rend(); ++it) axis.push_back(-*it);
  axis.insert(axis.end(), right.begin() + 1, right.end());
  return axis;
}

// Quarter model: the body's x = 0 and y = 0 faces become the node sets `<to>x` and `<to>y` for the
// symmetry conditions; their side sets go (they are not boundaries of the physical problem).
void keep_symmetry_planes(Mesh& m, const std::string& body, const std::string& to) {
  for (const char* axis : {"x", "y"}) {
    const std::string face = body + "_" + axis + "min";
    m.node_sets[to + axis] = std::move(m.node_sets.at(face));
    m.node_sets.erase(face);
    m.side_sets.erase(face);
  }
}

// A node set `name` of the one node of set `of` nearest the axis x = y = 0 (the apex, the loaded top).
void axis_node_set(Mesh& m, const std::string& name, const std::string& of,
                   const std::function<std::array<double, 2>(int)>& xy) {
  m.node_sets[name] = {nearest_node(xy, m.node_sets.at(of), 0.0, 0.0)};
}

/// z of the tip's bottom face above the point (x, y), m (the apex at (0, 0, gap)).
double tip_bottom_z(const AsperitySpec& s, double x, double y) {
  if (s.paraboloid) return s.gap + (x * x + y * y) / (2.0 * s.radius);  // Hertz's profile
  return s.gap + s.radius - std::sqrt(s.radius * s.radius - x * x - y * y);
}

}  // namespace

std::vector<double> graded_axis(double lo, double hi, double h, double fine, double ratio) {
  std::vector<double> x{lo};
  const double length = hi - lo;
  // A fine region shorter than one element (e.g. none left below a coating) is one element of h.
  const double fine_length = std::min(std::max(fine, h), length);
  const int n_fine = std::max(1, static_cast<int>(std::ceil(fine_length / h - 1e-9)));
  const double hf = fine_length / n_fine;
  for (int i = 1; i <= n_fine; ++i) x.push_back(lo + i * hf);
  double size = hf;
  while (x.back() < hi - 1e-12 * length) {
    size *= ratio;
    const double next = x.back() + size;
    // Absorb a last sliver (under half an element) into the previous element.
    if (next >= hi || hi - next < 0.5 * size * ratio) {
      x.push_back(hi);
      break;
    }
    x.push_back(next);
  }
  x.back() = hi;
  return x;
}

namespace {

// The grids' axes of the asperity: the substrate's (with the first coating element layer, or -1) and the tip's.
struct AsperityAxes {
  std::array<std::vector<double>, 3> substrate, tip;
  int coating_k = -1;
};

AsperityAxes asperity_axes(const AsperitySpec& s) {
  if (const auto violations = asperity_limit_violations(s); !violations.empty()) {
    std::string message;  // one line per violated limit (the deck set-up puts each at its key's line)
    for (const auto& v : violations) {
      if (!message.empty()) message += '\n';
      message += "asperity mesh: '";
      message += v.key;
      message += "': ";
      message += v.message;
    }
    throw MeshError(message);
  }
  AsperityAxes a;
  const double h = s.element_size, r = s.grading_ratio;
  // Substrate (and coating): z from -depth to 0, fine near the top.
  auto& sub_axes = a.substrate;
  sub_axes[1] = lateral_axis(0.5 * s.substrate_width, h, s.fine_half_width, r, s.quarter);
  sub_axes[0] = s.fine_x_range ? fine_range_axis(0.5 * s.substrate_width, h, *s.fine_x_range, r, s.quarter) : sub_axes[1];
  std::vector<double> z;
  if (s.coating_thickness > 0.0) {
    const double hc = s.coating_thickness / s.coating_layers;
    // Below the coating, start again from h and grade down (not from the coating's layer
    // thickness: a very thin coating would otherwise fill the substrate with thin layers that set
    // the stable time step).
    std::vector<double> below = graded_axis(0.0, s.substrate_depth - s.coating_thickness, h,
                                            std::max(0.0, s.fine_depth - s.coating_thickness), r);
    for (auto it = below.rbegin(); it != below.rend(); ++it) z.push_back(-s.coating_thickness - *it);
    a.coating_k = static_cast<int>(z.size()) - 1;
    for (int i = 1; i <= s.coating_layers; ++i) z.push_back(-s.coating_thickness + i * hc);
  } else {
    const std::vector<double> down = graded_axis(0.0, s.substrate_depth, h, s.fine_depth, r);
    for (auto it = down.rbegin(); it != down.rend(); ++it) z.push_back(-*it);
  }
  sub_axes[2] = z;
  // Tip: a column on [-w/2, w/2]^2 x [0, H] mapped so that its bottom follows the sphere.
  a.tip[0] = lateral_axis(0.5 * s.tip_width, h, s.fine_half_width, r, s.quarter);
  a.tip[1] = a.tip[0];
  a.tip[2] = graded_axis(0.0, s.tip_height, h, s.fine_depth, r);
  return a;
}

// The substrate's blocks (the coating split off its top layers) and sets, on its grid's (from
// generate_grid or plan_grid); `xy` gives a node's x and y (for the axis nodes).
void substrate_sets(Mesh& sub, const AsperityAxes& a, bool quarter, const std::function<std::array<double, 2>(int)>& xy) {
  if (a.coating_k >= 0) {
    const int layer = static_cast<int>((a.substrate[0].size() - 1) * (a.substrate[1].size() - 1));
    const int split = a.coating_k * layer;
    const int total = sub.blocks.front().element_count;
    sub.blocks = {{"substrate", 0, split}, {"coating", split, total - split}};
  }
  rename(sub, "substrate_zmax", "substrate_top");
  rename(sub, "substrate_zmin", "substrate_bottom");
  merge_sides(sub, "substrate", "substrate_sides", quarter);
  axis_node_set(sub, "substrate_axis_bottom", "substrate_bottom", xy);
  axis_node_set(sub, "substrate_axis_top", "substrate_top", xy);
  if (quarter) keep_symmetry_planes(sub, "substrate", "symmetry_");
}

void tip_sets(Mesh& tip, bool quarter, const std::function<std::array<double, 2>(int)>& xy) {
  rename(tip, "tip_zmin", "tip_surface");
  rename(tip, "tip_zmax", "tip_top");
  merge_sides(tip, "tip", "tip_sides", quarter);
  axis_node_set(tip, "tip_axis_top", "tip_top", xy);
  axis_node_set(tip, "tip_apex", "tip_surface", xy);
  if (quarter) keep_symmetry_planes(tip, "tip", "tip_symmetry_");
}

// Quarter model: the tip's symmetry-plane nodes join the substrate's (after the two are appended).
void join_symmetry_planes(std::map<std::string, std::vector<int>>& node_sets) {
  for (const char* axis : {"x", "y"}) {
    const std::string tip_set = std::string("tip_symmetry_") + axis;
    std::vector<int>& plane = node_sets.at(std::string("symmetry_") + axis);
    const std::vector<int>& from_tip = node_sets.at(tip_set);
    plane.insert(plane.end(), from_tip.begin(), from_tip.end());
    std::sort(plane.begin(), plane.end());
    node_sets.erase(tip_set);
  }
}

// The tip's z' in [0, H] -> [zb, top], so fine layers stay fine next to the curved face.
void map_tip_node(const AsperitySpec& s, double* x) {
  const double top = s.gap + s.tip_height;
  const double zb = tip_bottom_z(s, x[0], x[1]);
  x[2] = zb + x[2] / s.tip_height * (top - zb);
}

// `apex position`: the rigid translation (0, 0, gap) -> apex.
std::array<double, 3> apex_shift(const AsperitySpec& s) { return {s.apex[0], s.apex[1], s.apex[2] - s.gap}; }

// A grid's x and y of a node (its own numbering), as generate_grid writes them.
std::function<std::array<double, 2>(int)> grid_xy(const std::array<std::vector<double>, 3>& axes) {
  return [&axes](int n) {
    const int nx1 = static_cast<int>(axes[0].size()), ny1 = static_cast<int>(axes[1].size());
    return std::array<double, 2>{axes[0][static_cast<std::size_t>(n % nx1)], axes[1][static_cast<std::size_t>((n / nx1) % ny1)]};
  };
}

// The sets of a plan moved into a mesh for the set functions above, and back.
Mesh sets_of(GeneratedPlan& p) {
  Mesh m;
  m.blocks = std::move(p.blocks);
  m.node_sets = std::move(p.node_sets);
  m.side_sets = std::move(p.side_sets);
  return m;
}
void sets_back(GeneratedPlan& p, Mesh& m) {
  p.blocks = std::move(m.blocks);
  p.node_sets = std::move(m.node_sets);
  p.side_sets = std::move(m.side_sets);
}

}  // namespace

Mesh generate_asperity(const AsperitySpec& s) {
  const AsperityAxes a = asperity_axes(s);
  Mesh sub = generate_grid("substrate", a.substrate);
  substrate_sets(sub, a, s.quarter, grid_xy(a.substrate));
  Mesh tip = generate_grid("tip", a.tip);
  for (int n = 0; n < tip.node_count(); ++n) map_tip_node(s, &tip.coordinates[3 * static_cast<std::size_t>(n)]);
  tip_sets(tip, s.quarter, grid_xy(a.tip));
  Mesh mesh;
  if (s.tip_only) {
    mesh = std::move(tip);
  } else {
    mesh = std::move(sub);
    append(mesh, tip);
  }
  if (s.place_apex) {
    const std::array<double, 3> shift = apex_shift(s);
    for (int n = 0; n < mesh.node_count(); ++n)
      for (int i = 0; i < 3; ++i) mesh.coordinates[3 * n + i] += shift[i];
  }
  if (s.quarter) join_symmetry_planes(mesh.node_sets);
  validate(mesh, "asperity mesh");
  return mesh;
}

GeneratedPlan plan_asperity(const AsperitySpec& s) {
  const AsperityAxes a = asperity_axes(s);
  GeneratedPlan sub = plan_grid("substrate", a.substrate);
  Mesh sets = sets_of(sub);
  substrate_sets(sets, a, s.quarter, grid_xy(a.substrate));
  sets_back(sub, sets);
  GeneratedPlan tip = plan_grid("tip", a.tip);
  tip.grids.front().map = [s](double* x) { map_tip_node(s, x); };
  sets = sets_of(tip);
  tip_sets(sets, s.quarter, grid_xy(a.tip));
  sets_back(tip, sets);
  GeneratedPlan plan;
  if (s.tip_only) {
    plan = std::move(tip);
  } else {
    plan = std::move(sub);
    append_plan(plan, std::move(tip));
  }
  if (s.place_apex) {
    const std::array<double, 3> shift = apex_shift(s);
    for (GridPiece& g : plan.grids) {
      // After the grid's own map, as generate_asperity translates the mapped mesh.
      g.map = [inner = g.map, shift](double* x) {
        if (inner) inner(x);
        for (int i = 0; i < 3; ++i) x[i] += shift[i];
      };
    }
  }
  if (s.quarter) join_symmetry_planes(plan.node_sets);
  return plan;
}

}  // namespace tribex::mesh
