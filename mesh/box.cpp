// SPDX-License-Identifier: MIT
// Structured hex8 box. Node (i,j,k) has index i + (nx+1)(j + (ny+1)k); element (i,j,k) has index
// i + nx(j + ny k) (x fastest). Optional geometric grading along one axis:
//   h_m = h_0 r^m (m = 0 at the named face),  sum_{m<n} h_m = h_0 (r^n - 1)/(r - 1) = L.
#include "mesh/box.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "mesh/grid_cell.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh {

namespace {

const char* const face_names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
// Local hex8 face (hex8_face_nodes) lying on each box face, same order as face_names.
constexpr int box_face_to_local[6] = {3, 1, 0, 2, 4, 5};

/// Node coordinates along one axis: n+1 values from origin to origin+length (the last is set exactly).
std::vector<double> axis_coordinates(double origin, double length, int n, double ratio, bool toward_min,
                                     bool toward_max) {
  std::vector<double> x(static_cast<std::size_t>(n) + 1);
  if (!toward_min && !toward_max) {
    for (int i = 0; i <= n; ++i) x[i] = origin + length * i / n;
  } else {
    // Smallest size h0 at the named face (see header comment); r = 1 degenerates to uniform.
    const double h0 = ratio == 1.0 ? length / n : length * (ratio - 1.0) / (std::pow(ratio, n) - 1.0);
    std::vector<double> h(static_cast<std::size_t>(n));
    for (int m = 0; m < n; ++m) h[toward_min ? m : n - 1 - m] = h0 * std::pow(ratio, m);
    x[0] = origin;
    for (int i = 0; i < n; ++i) x[i + 1] = x[i] + h[i];
  }
  x[n] = origin + length;  // total length exact, independent of round-off in the series
  return x;
}

// Every set a grid NAME makes (node sets: these and NAME_all; side sets: these).
std::vector<std::string> set_names(const std::string& name) {
  std::vector<std::string> names;
  for (const char* f : face_names) names.push_back(name + "_" + f);
  return names;
}

// A grid added to a mesh must not reuse a block or set name (as append).
void check_new_names(const Mesh& into, const std::vector<std::string>& blocks, const std::vector<std::string>& sets) {
  for (const auto& b : blocks)
    if (into.find_block(b)) throw MeshError("append: both meshes have a block named '" + b + "'; rename one of them");
  std::vector<std::string> node_sets = sets;
  node_sets.push_back(blocks.front() + "_all");
  for (const auto& s : node_sets)
    if (into.node_sets.count(s)) throw MeshError("append: both meshes have a node set named '" + s + "'; rename one of them");
  for (const auto& s : sets)
    if (into.side_sets.count(s)) throw MeshError("append: both meshes have a side set named '" + s + "'; rename one of them");
}

// The face sets of a grid of n_el elements numbered from the offsets (add_grid; a generated plan's
// sets, generated_plan.hpp): side sets and node sets NAME_xmin .. NAME_zmax, not NAME_all.
void add_grid_sets(Mesh& mesh, const std::string& name, const std::array<std::int64_t, 3>& n_el, std::int64_t node_offset,
                   std::int64_t element_offset) {
  const std::int64_t nx = n_el[0], ny = n_el[1];
  const auto node = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<int>(node_offset + i + (nx + 1) * (j + (ny + 1) * k));
  };
  // Boundary sets. For face f, loop the two in-plane axes; the element and node indices follow
  // from fixing the normal axis at its min or max.
  for (int f = 0; f < 6; ++f) {
    const int d = f / 2;
    const bool at_max = f % 2 == 1;
    const int a = (d + 1) % 3, b = (d + 2) % 3;  // in-plane axes
    std::vector<Side>& sides = mesh.side_sets[name + "_" + face_names[f]];
    std::vector<int>& nodes = mesh.node_sets[name + "_" + face_names[f]];
    sides.reserve(static_cast<std::size_t>(n_el[a] * n_el[b]));
    nodes.reserve(static_cast<std::size_t>((n_el[a] + 1) * (n_el[b] + 1)));
    std::int64_t ijk[3];
    for (std::int64_t u = 0; u < n_el[a]; ++u)
      for (std::int64_t v = 0; v < n_el[b]; ++v) {
        ijk[d] = at_max ? n_el[d] - 1 : 0;
        ijk[a] = u;
        ijk[b] = v;
        sides.push_back({static_cast<int>(element_offset + ijk[0] + nx * (ijk[1] + ny * ijk[2])), box_face_to_local[f]});
      }
    for (std::int64_t u = 0; u <= n_el[a]; ++u)
      for (std::int64_t v = 0; v <= n_el[b]; ++v) {
        ijk[d] = at_max ? n_el[d] : 0;
        ijk[a] = u;
        ijk[b] = v;
        nodes.push_back(node(ijk[0], ijk[1], ijk[2]));
      }
    std::sort(sides.begin(), sides.end(), [](const Side& s, const Side& t) { return s.element < t.element; });
    std::sort(nodes.begin(), nodes.end());
  }
}

// The grid's element counts along x, y, z; MeshError for axes that do not increase or a mesh past int.
std::array<std::int64_t, 3> check_grid(const std::string& name, const std::array<std::vector<double>, 3>& axes,
                                       std::int64_t node_offset, std::int64_t element_offset) {
  const std::string source = "structured grid '" + name + "'";
  for (int d = 0; d < 3; ++d) {
    if (axes[d].size() < 2) throw MeshError(source + ": an axis needs at least 2 coordinates");
    for (std::size_t i = 1; i < axes[d].size(); ++i)
      if (!(axes[d][i] > axes[d][i - 1])) throw MeshError(source + ": axis coordinates must increase strictly");
  }
  const std::int64_t nx = static_cast<std::int64_t>(axes[0].size()) - 1, ny = static_cast<std::int64_t>(axes[1].size()) - 1,
                     nz = static_cast<std::int64_t>(axes[2].size()) - 1;
  const std::int64_t node_count = (nx + 1) * (ny + 1) * (nz + 1);
  const std::int64_t element_count = nx * ny * nz;
  // Arrays are indexed by int: keep 8 * elements and 3 * nodes below INT_MAX.
  if (element_offset + element_count > std::numeric_limits<int>::max() / 8 ||
      node_offset + node_count > std::numeric_limits<int>::max() / 3)
    throw MeshError(source + ": " + std::to_string(element_offset + element_count) +
                    " elements exceed the int index range; use fewer intervals");
  return {nx, ny, nz};
}

// The grid of `axes` added to `mesh` in place (add_box, generate_grid).
void add_grid(Mesh& mesh, const std::string& name, const std::array<std::vector<double>, 3>& axes) {
  const std::int64_t node_offset = mesh.node_count(), element_offset = mesh.element_count();
  const auto [nx, ny, nz] = check_grid(name, axes, node_offset, element_offset);
  const std::int64_t node_count = (nx + 1) * (ny + 1) * (nz + 1);
  const std::int64_t element_count = nx * ny * nz;
  check_new_names(mesh, {name}, set_names(name));

  mesh.coordinates.resize(static_cast<std::size_t>(node_offset + node_count) * 3);
  const auto node = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<int>(node_offset + i + (nx + 1) * (j + (ny + 1) * k));
  };
  std::size_t p = static_cast<std::size_t>(node_offset) * 3;
  for (std::int64_t k = 0; k <= nz; ++k)
    for (std::int64_t j = 0; j <= ny; ++j)
      for (std::int64_t i = 0; i <= nx; ++i) {
        mesh.coordinates[p++] = axes[0][i];
        mesh.coordinates[p++] = axes[1][j];
        mesh.coordinates[p++] = axes[2][k];
      }

  mesh.connectivity.resize(static_cast<std::size_t>(element_offset + element_count) * 8);
  p = static_cast<std::size_t>(element_offset) * 8;
  for (std::int64_t k = 0; k < nz; ++k)
    for (std::int64_t j = 0; j < ny; ++j)
      for (std::int64_t i = 0; i < nx; ++i) {
        grid_cell_nodes(node, i, j, k, &mesh.connectivity[p]);
        p += 8;
      }
  mesh.blocks.push_back({name, static_cast<int>(element_offset), static_cast<int>(element_count)});

  add_grid_sets(mesh, name, {nx, ny, nz}, node_offset, element_offset);
  std::vector<int>& all = mesh.node_sets[name + "_all"];
  all.resize(static_cast<std::size_t>(node_count));
  for (int n = 0; n < static_cast<int>(node_count); ++n) all[n] = static_cast<int>(node_offset) + n;
}

}  // namespace

Mesh generate_box(const BoxSpec& spec) {
  Mesh mesh;
  add_box(mesh, spec);
  return mesh;
}

std::array<long long, 2> box_size(const BoxSpec& spec) {
  long long nodes = 1, elements = 1;
  for (int n : spec.intervals) {
    if (n < 1) return {0, 0};
    nodes *= n + 1LL;
    elements *= n;
  }
  return {nodes, elements};
}

namespace {
// The checked spec's axes (add_box, plan_box).
std::array<std::vector<double>, 3> box_axes(const BoxSpec& spec) {
  const std::string source = "generated box '" + spec.name + "'";
  if (spec.name.empty()) throw MeshError("generated box: the block name is empty; give the box a name");
  const char* axis = "xyz";
  for (int d = 0; d < 3; ++d) {
    if (spec.intervals[d] < 1)
      throw MeshError(source + ": intervals along " + axis[d] + " is " + std::to_string(spec.intervals[d]) +
                      "; it must be at least 1");
    if (!(spec.size[d] > 0.0) || !std::isfinite(spec.size[d]))
      throw MeshError(source + ": size along " + axis[d] + " must be a positive finite length (m)");
    if (!std::isfinite(spec.origin[d])) throw MeshError(source + ": origin must be finite");
  }
  int graded_face = -1;
  if (!spec.grade_toward.empty()) {
    for (int f = 0; f < 6; ++f)
      if (spec.grade_toward == face_names[f]) graded_face = f;
    if (graded_face < 0)
      throw MeshError(source + ": grade_toward '" + spec.grade_toward +
                      "' is not a face; use one of xmin, xmax, ymin, ymax, zmin, zmax");
    if (!(spec.grading_ratio >= 1.0) || !std::isfinite(spec.grading_ratio))
      throw MeshError(source + ": grading_ratio must be >= 1 (smallest element at the named face); "
                      "to grow elements toward a face, grade toward the opposite face instead");
  } else if (spec.grading_ratio != 1.0) {
    throw MeshError(source + ": grading_ratio is set but grade_toward is empty; name the face to grade toward");
  }

  std::array<std::vector<double>, 3> axes;
  for (int d = 0; d < 3; ++d)
    axes[d] = axis_coordinates(spec.origin[d], spec.size[d], spec.intervals[d], spec.grading_ratio,
                               graded_face == 2 * d, graded_face == 2 * d + 1);
  return axes;
}
}  // namespace

void add_box(Mesh& into, const BoxSpec& spec) { add_grid(into, spec.name, box_axes(spec)); }

GeneratedPlan plan_box(const BoxSpec& spec) { return plan_grid(spec.name, box_axes(spec)); }

GeneratedPlan plan_grid(const std::string& name, const std::array<std::vector<double>, 3>& axes) {
  const std::array<std::int64_t, 3> n = check_grid(name, axes, 0, 0);
  GeneratedPlan plan;
  Mesh sets;  // the face sets alone: add_grid's, from the same function
  add_grid_sets(sets, name, n, 0, 0);
  GridPiece& g = plan.grids.emplace_back();
  g.axes = axes;
  plan.node_count = g.nodes();
  plan.element_count = g.elements();
  plan.blocks.push_back({name, 0, plan.element_count});
  plan.node_sets = std::move(sets.node_sets);
  plan.side_sets = std::move(sets.side_sets);
  plan.node_set_ranges[name + "_all"] = {0, plan.node_count};
  return plan;
}

Mesh generate_grid(const std::string& name, const std::array<std::vector<double>, 3>& axes) {
  Mesh mesh;
  add_grid(mesh, name, axes);
  return mesh;
}


}  // namespace tribex::mesh
