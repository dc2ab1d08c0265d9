// SPDX-License-Identifier: MIT
// generated_plan.hpp: a generated mesh's elements and nodes computed from its grids (node and element
// numbering of box.cpp's add_grid, the same arithmetic for the coordinates).
#include "mesh/generated_plan.hpp"

#include <algorithm>
#include <iterator>

#include "mesh/grid_cell.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

// The grid holding global number `number`: offsets ascend, so the last grid starting at or below it.
template <typename Offset>
const GridPiece& grid_of(const GeneratedPlan& plan, int number, Offset offset) {
  auto it = std::upper_bound(plan.grids.begin(), plan.grids.end(), number,
                             [&](int n, const GridPiece& g) { return n < offset(g); });
  return *std::prev(it);
}

// The 8 global nodes of global element e, in the hex8 order add_grid writes them.
void corners(const GeneratedPlan& plan, int e, int* c) {
  const GridPiece& g = grid_of(plan, e, [](const GridPiece& p) { return p.element_offset; });
  const int nx = static_cast<int>(g.axes[0].size()) - 1, ny = static_cast<int>(g.axes[1].size()) - 1;
  const int local = e - g.element_offset;
  const int i = local % nx, j = (local / nx) % ny, k = local / (nx * ny);
  const auto node = [&](int a, int b, int d) { return g.node_offset + a + (nx + 1) * (b + (ny + 1) * d); };
  grid_cell_nodes(node, i, j, k, c);
}

// The coordinates of global node n: the axes at (i, j, k), then the grid's map (generate_asperity
// writes the axes into the mesh and maps them in place: the same operations on the same values).
void node_xyz(const GeneratedPlan& plan, int n, double* x) {
  const GridPiece& g = grid_of(plan, n, [](const GridPiece& p) { return p.node_offset; });
  const int nx1 = static_cast<int>(g.axes[0].size()), ny1 = static_cast<int>(g.axes[1].size());
  const int local = n - g.node_offset;
  x[0] = g.axes[0][static_cast<std::size_t>(local % nx1)];
  x[1] = g.axes[1][static_cast<std::size_t>((local / nx1) % ny1)];
  x[2] = g.axes[2][static_cast<std::size_t>(local / (nx1 * ny1))];
  if (g.map) g.map(x);
}

// The whole mesh's sets restricted to the nodes `global_node` and elements `elements` (both sorted),
// in local numbers, in each set's order (split_mesh's restriction, parallel/mesh_part.cpp).
void restrict_sets(const GeneratedPlan& plan, const std::vector<int>& elements, const std::vector<int>& global_node,
                   Mesh& m) {
  const auto local_node = [&](int n) {
    const auto at = std::lower_bound(global_node.begin(), global_node.end(), n);
    return at != global_node.end() && *at == n ? static_cast<int>(at - global_node.begin()) : -1;
  };
  for (const auto& [name, nodes] : plan.node_sets) {
    std::vector<int>& out = m.node_sets[name];
    for (int n : nodes)
      if (const int l = local_node(n); l >= 0) out.push_back(l);
  }
  for (const auto& [name, range] : plan.node_set_ranges) {
    std::vector<int>& out = m.node_sets[name];
    const auto first = std::lower_bound(global_node.begin(), global_node.end(), range[0]);
    const auto last = std::lower_bound(first, global_node.end(), range[1]);
    for (auto it = first; it != last; ++it) out.push_back(static_cast<int>(it - global_node.begin()));
  }
  for (const auto& [name, sides] : plan.side_sets) {
    std::vector<Side>& out = m.side_sets[name];
    for (const Side& s : sides) {
      const auto at = std::lower_bound(elements.begin(), elements.end(), s.element);
      if (at != elements.end() && *at == s.element) out.push_back({static_cast<int>(at - elements.begin()), s.face});
    }
  }
}

}  // namespace

int GridPiece::nodes() const {
  return static_cast<int>(axes[0].size() * axes[1].size() * axes[2].size());
}

int GridPiece::elements() const {
  return static_cast<int>((axes[0].size() - 1) * (axes[1].size() - 1) * (axes[2].size() - 1));
}

std::map<std::string, int> GeneratedPlan::node_set_sizes() const {
  std::map<std::string, int> sizes;
  for (const auto& [name, nodes] : node_sets) sizes[name] = static_cast<int>(nodes.size());
  for (const auto& [name, range] : node_set_ranges) sizes[name] = range[1] - range[0];
  return sizes;
}

std::map<std::string, int> GeneratedPlan::side_set_sizes() const {
  std::map<std::string, int> sizes;
  for (const auto& [name, sides] : side_sets) sizes[name] = static_cast<int>(sides.size());
  return sizes;
}

std::vector<int> element_nodes(const GeneratedPlan& plan, int first, int count) {
  std::vector<int> nodes(8 * static_cast<std::size_t>(count));
  for (int e = 0; e < count; ++e) corners(plan, first + e, &nodes[8 * static_cast<std::size_t>(e)]);
  return nodes;
}

int grid_of_node(const GeneratedPlan& plan, int node) {
  return static_cast<int>(&grid_of(plan, node, [](const GridPiece& p) { return p.node_offset; }) - plan.grids.data());
}

std::vector<double> node_coordinates(const GeneratedPlan& plan, int first, int count) {
  std::vector<double> x(3 * static_cast<std::size_t>(count));
  for (int n = 0; n < count; ++n) node_xyz(plan, first + n, &x[3 * static_cast<std::size_t>(n)]);
  return x;
}

Mesh generate_elements(const GeneratedPlan& plan, const std::vector<int>& elements, std::vector<int>& global_node) {
  Mesh m;
  const std::size_t ne = elements.size();
  m.connectivity.resize(8 * ne);
  for (std::size_t e = 0; e < ne; ++e) corners(plan, elements[e], &m.connectivity[8 * e]);
  // The nodes, ascending: local order = global order (MeshPart's numbering).
  global_node = m.connectivity;
  std::sort(global_node.begin(), global_node.end());
  global_node.erase(std::unique(global_node.begin(), global_node.end()), global_node.end());
  global_node.shrink_to_fit();
  for (int& n : m.connectivity)
    n = static_cast<int>(std::lower_bound(global_node.begin(), global_node.end(), n) - global_node.begin());
  m.coordinates.resize(3 * global_node.size());
  for (std::size_t l = 0; l < global_node.size(); ++l) node_xyz(plan, global_node[l], &m.coordinates[3 * l]);
  // Blocks are contiguous ranges of global elements, so of local ones too.
  for (const Block& b : plan.blocks) {
    const auto first = std::lower_bound(elements.begin(), elements.end(), b.first_element);
    const auto last = std::lower_bound(first, elements.end(), b.first_element + b.element_count);
    m.blocks.push_back({b.name, static_cast<int>(first - elements.begin()), static_cast<int>(last - first)});
  }
  restrict_sets(plan, elements, global_node, m);
  return m;
}

void append_plan(GeneratedPlan& into, GeneratedPlan other) {
  const auto clash = [](const char* what, const std::string& name) {
    throw MeshError(std::string("append: both meshes have a ") + what + " named '" + name + "'; rename one of them");
  };
  for (const Block& b : other.blocks)
    for (const Block& c : into.blocks)
      if (b.name == c.name) clash("block", b.name);
  for (const auto& sizes : {other.node_set_sizes()})
    for (const auto& [name, n] : sizes)
      if (into.node_sets.count(name) || into.node_set_ranges.count(name)) clash("node set", name);
  for (const auto& [name, sides] : other.side_sets)
    if (into.side_sets.count(name)) clash("side set", name);
  const int dn = into.node_count, de = into.element_count;
  for (GridPiece& g : other.grids) {
    g.node_offset += dn;
    g.element_offset += de;
    into.grids.push_back(std::move(g));
  }
  for (Block b : other.blocks) {
    b.first_element += de;
    into.blocks.push_back(b);
  }
  for (auto& [name, nodes] : other.node_sets) {
    for (int& n : nodes) n += dn;
    into.node_sets[name] = std::move(nodes);
  }
  for (const auto& [name, range] : other.node_set_ranges) into.node_set_ranges[name] = {range[0] + dn, range[1] + dn};
  for (auto& [name, sides] : other.side_sets) {
    for (Side& s : sides) s.element += de;
    into.side_sets[name] = std::move(sides);
  }
  into.node_count += other.node_count;
  into.element_count += other.element_count;
}

}  // namespace tribex::mesh
