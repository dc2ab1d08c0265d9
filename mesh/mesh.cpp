// SPDX-License-Identifier: MIT
// Mesh queries, append and validation. Geometry of the trilinear hex8 (docs/theory.md section 2.1):
// x(xi,eta,zeta) = sum_I N_I x_I, N_I = (1/8)(1+xi_I xi)(1+eta_I eta)(1+zeta_I zeta).
#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {

namespace {

using Vec3 = std::array<double, 3>;

// Reference coordinates (xi, eta, zeta) of the 8 corners, hex8 order of mesh.hpp.
constexpr int corner_sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
// For each corner, the neighbouring corner along xi, eta and zeta.
constexpr int corner_neighbour[8][3] = {{1, 3, 4}, {0, 2, 5}, {3, 1, 6}, {2, 0, 7},
                                        {5, 7, 0}, {4, 6, 1}, {7, 5, 2}, {6, 4, 3}};

Vec3 node_xyz(const Mesh& m, int node) {
  const auto n = static_cast<std::size_t>(node) * 3;
  return {m.coordinates[n], m.coordinates[n + 1], m.coordinates[n + 2]};
}

double det3(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

double norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/// The Jacobian columns dx/dxi, dx/deta, dx/dzeta at corner c (c = 0..7) or at the centre (c = 8).
/// At a corner only the 3 edges leaving it contribute: dx/dxi = (x_{xi=+1} - x_{xi=-1}) / 2.
/// At the centre dx/dxi_k = (1/8) sum_I sign_Ik x_I.
std::array<Vec3, 3> jacobian_columns(const std::array<Vec3, 8>& x, int c) {
  std::array<Vec3, 3> J{};
  if (c < 8) {
    for (int k = 0; k < 3; ++k) {
      const Vec3& nb = x[corner_neighbour[c][k]];
      const double s = 0.5 * corner_sign[c][k];  // +1 corner: x_c - x_nb; -1 corner: x_nb - x_c
      for (int d = 0; d < 3; ++d) J[k][d] = s * (x[c][d] - nb[d]);
    }
  } else {
    for (int I = 0; I < 8; ++I)
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d) J[k][d] += 0.125 * corner_sign[I][k] * x[I][d];
  }
  return J;
}

std::array<Vec3, 8> element_xyz(const Mesh& m, int e) {
  std::array<Vec3, 8> x{};
  for (int a = 0; a < 8; ++a) x[a] = node_xyz(m, m.connectivity[8 * static_cast<std::size_t>(e) + a]);
  return x;
}

/// det(J) / (|J1||J2||J3|) at corner c (or centre, c = 8); 0 for a degenerate edge.
double scaled_det(const std::array<Vec3, 3>& J) {
  const double scale = norm(J[0]) * norm(J[1]) * norm(J[2]);
  if (!(scale > 0.0)) return 0.0;
  return det3(J[0], J[1], J[2]) / scale;
}

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw MeshError(source + ": " + what);
}

std::string block_of(const Mesh& m, int e) {
  for (const Block& b : m.blocks)
    if (e >= b.first_element && e < b.first_element + b.element_count) return " (block '" + b.name + "')";
  return "";
}

void check_index_ranges(const Mesh& mesh, const std::string& source) {
  if (mesh.coordinates.size() % 3 != 0)
    fail(source, "coordinates array length " + std::to_string(mesh.coordinates.size()) +
                     " is not a multiple of 3 ([node][3] layout)");
  if (mesh.connectivity.size() % 8 != 0)
    fail(source, "connectivity array length " + std::to_string(mesh.connectivity.size()) +
                     " is not a multiple of 8 ([element][8] layout, hex8 only)");
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i)
    if (!std::isfinite(mesh.coordinates[i]))
      fail(source, "node " + std::to_string(i / 3 + 1) + " has a non-finite coordinate");
  const int nn = mesh.node_count();
  const int ne = mesh.element_count();
  for (int e = 0; e < ne; ++e)
    for (int a = 0; a < 8; ++a) {
      const int n = mesh.connectivity[8 * static_cast<std::size_t>(e) + a];
      if (n < 0 || n >= nn)
        fail(source, "element " + std::to_string(e + 1) + block_of(mesh, e) + " node " + std::to_string(a) +
                         " refers to node index " + std::to_string(n) + ", outside 0.." +
                         std::to_string(nn - 1));
    }
}

void check_blocks(const Mesh& mesh, const std::string& source) {
  const int ne = mesh.element_count();
  std::vector<const Block*> sorted;
  for (const Block& b : mesh.blocks) {
    if (b.name.empty()) fail(source, "a block has an empty name; give every block a name");
    if (b.element_count < 0 || b.first_element < 0 || b.first_element + b.element_count > ne)
      fail(source, "block '" + b.name + "' covers elements " + std::to_string(b.first_element + 1) + ".." +
                       std::to_string(b.first_element + b.element_count) + " but the mesh has " +
                       std::to_string(ne) + " elements");
    sorted.push_back(&b);
  }
  std::sort(sorted.begin(), sorted.end(),
            [](const Block* a, const Block* b) { return a->first_element < b->first_element; });
  for (std::size_t i = 0; i < mesh.blocks.size(); ++i)
    for (std::size_t j = i + 1; j < mesh.blocks.size(); ++j)
      if (mesh.blocks[i].name == mesh.blocks[j].name)
        fail(source, "two blocks are named '" + mesh.blocks[i].name + "'; block names must be unique");
  int next = 0;  // first element not yet covered by a block
  for (const Block* b : sorted) {
    if (b->first_element > next)
      fail(source, "element " + std::to_string(next + 1) + " belongs to no block; every element must be in exactly one block");
    if (b->first_element < next)
      fail(source, "element " + std::to_string(b->first_element + 1) + " belongs to two blocks (block '" + b->name +
                       "' overlaps another); every element must be in exactly one block");
    next = b->first_element + b->element_count;
  }
  if (next < ne)
    fail(source, "element " + std::to_string(next + 1) + " belongs to no block; every element must be in exactly one block");
}

void check_sets(const Mesh& mesh, const std::string& source) {
  const int nn = mesh.node_count();
  for (const auto& [name, nodes] : mesh.node_sets)
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (nodes[i] < 0 || nodes[i] >= nn)
        fail(source, "node set '" + name + "' refers to node index " + std::to_string(nodes[i]) + ", outside 0.." +
                         std::to_string(nn - 1));
      if (i > 0 && nodes[i] <= nodes[i - 1])
        fail(source, "node set '" + name + "' is not sorted and unique at entry " + std::to_string(i + 1));
    }
  const int ne = mesh.element_count();
  for (const auto& [name, sides] : mesh.side_sets)
    for (const Side& s : sides)
      if (s.element < 0 || s.element >= ne || s.face < 0 || s.face > 5)
        fail(source, "side set '" + name + "' has side (element index " + std::to_string(s.element) + ", face " +
                         std::to_string(s.face) + "); elements are 0.." + std::to_string(ne - 1) +
                         ", faces 0..5");
}

std::string format_double(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

}  // namespace

const Block* Mesh::find_block(const std::string& name) const {
  for (const Block& b : blocks)
    if (b.name == name) return &b;
  return nullptr;
}

std::array<int, 4> Mesh::side_nodes(const Side& s) const {
  std::array<int, 4> out{};
  const auto base = 8 * static_cast<std::size_t>(s.element);
  for (int k = 0; k < 4; ++k) out[k] = connectivity[base + hex8_face_nodes[s.face][k]];
  return out;
}

std::vector<int> Mesh::side_set_nodes(const std::string& name) const {
  const auto it = side_sets.find(name);
  if (it == side_sets.end()) throw MeshError("the mesh has no side set named '" + name + "'");
  std::vector<int> nodes;
  nodes.reserve(it->second.size() * 4);
  for (const Side& s : it->second)
    for (int n : side_nodes(s)) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

void append(Mesh& into, const Mesh& other) {
  for (const Block& b : other.blocks)
    if (into.find_block(b.name))
      throw MeshError("append: both meshes have a block named '" + b.name + "'; rename one of them");
  for (const auto& [name, nodes] : other.node_sets)
    if (into.node_sets.count(name))
      throw MeshError("append: both meshes have a node set named '" + name + "'; rename one of them");
  for (const auto& [name, sides] : other.side_sets)
    if (into.side_sets.count(name))
      throw MeshError("append: both meshes have a side set named '" + name + "'; rename one of them");

  const int node_offset = into.node_count();
  const int element_offset = into.element_count();
  into.coordinates.insert(into.coordinates.end(), other.coordinates.begin(), other.coordinates.end());
  into.connectivity.reserve(into.connectivity.size() + other.connectivity.size());
  for (int n : other.connectivity) into.connectivity.push_back(n + node_offset);
  for (Block b : other.blocks) {
    b.first_element += element_offset;
    into.blocks.push_back(b);
  }
  for (const auto& [name, nodes] : other.node_sets) {
    std::vector<int>& dst = into.node_sets[name];
    dst.reserve(nodes.size());
    for (int n : nodes) dst.push_back(n + node_offset);
  }
  for (const auto& [name, sides] : other.side_sets) {
    std::vector<Side>& dst = into.side_sets[name];
    dst.reserve(sides.size());
    for (Side s : sides) dst.push_back({s.element + element_offset, s.face});
  }
}

BoundingBox bounding_box(const Mesh& mesh) {
  BoundingBox box;
  box.lo.fill(std::numeric_limits<double>::infinity());
  box.hi.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) {
    box.lo[i % 3] = std::min(box.lo[i % 3], mesh.coordinates[i]);
    box.hi[i % 3] = std::max(box.hi[i % 3], mesh.coordinates[i]);
  }
  return box;
}

void validate(const Mesh& mesh, const std::string& source) {
  check_index_ranges(mesh, source);
  check_blocks(mesh, source);
  check_sets(mesh, source);
  // An element is accepted if det(J) > 0 at the 8 corners and the centre. The threshold is on the
  // scaled determinant det(J)/(|J1||J2||J3|) (dimensionless, so independent of the element size):
  // below 1e-12 the corner is degenerate to round-off and the element would have zero or negative
  // volume there.
  constexpr double min_scaled_det = 1e-12;
  const int ne = mesh.element_count();
  for (int e = 0; e < ne; ++e) {
    const auto x = element_xyz(mesh, e);
    for (int c = 0; c <= 8; ++c) {
      const auto J = jacobian_columns(x, c);
      const double sd = scaled_det(J);
      if (!(sd > min_scaled_det)) {
        const std::string where =
            c < 8 ? "corner " + std::to_string(c) + " (node index " +
                        std::to_string(mesh.connectivity[8 * static_cast<std::size_t>(e) + c]) + ")"
                  : std::string("the centre");
        fail(source, "element " + std::to_string(e + 1) + block_of(mesh, e) + " is inverted or degenerate: det(J) = " +
                         format_double(det3(J[0], J[1], J[2])) + " at " + where +
                         "; the hex8 node order must be bottom face 0-3 counter-clockwise seen from above, then top 4-7");
      }
    }
  }
}

double scaled_jacobian(const Mesh& mesh, int element) {
  const auto x = element_xyz(mesh, element);
  double worst = 1.0;
  for (int c = 0; c < 8; ++c) worst = std::min(worst, scaled_det(jacobian_columns(x, c)));
  return worst;
}

}  // namespace tribex::mesh
