// SPDX-License-Identifier: MIT
// The mesh: nodes, hex8 element blocks, node sets and side sets. Plain data, contiguous arrays.
//
// Layouts (0-based indices everywhere):
//   coordinates   [node][3]    x, y, z of node n at 3n, 3n+1, 3n+2 (m)
//   connectivity  [element][8] node indices of element e at 8e..8e+7, in the hex8 order of
//                              docs/theory.md section 2.1: (xi,eta,zeta) = 0(---) 1(+--) 2(++-) 3(-+-)
//                              4(--+) 5(+-+) 6(+++) 7(-++) (also gmsh's and Exodus's order)
//   blocks        each block owns the contiguous element range [first_element, first_element+count)
//   side sets     (element, local face) pairs; local faces numbered as Exodus sides, see
//                 hex8_face_nodes (nodes counter-clockwise seen from outside: outward normal)
#pragma once

#include <array>
#include <compare>
#include <map>
#include <string>
#include <vector>

namespace tribex::mesh {

/// Local node indices of the 6 faces of a hex8, counter-clockwise seen from outside the element
/// (Exodus side numbering 1..6 minus one): 0: eta=-1, 1: xi=+1, 2: eta=+1, 3: xi=-1, 4: zeta=-1,
/// 5: zeta=+1.
inline constexpr int hex8_face_nodes[6][4] = {
    {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};

struct Side {
  int element = 0;
  int face = 0;  // 0..5, see hex8_face_nodes
  friend bool operator==(const Side&, const Side&) = default;
  friend auto operator<=>(const Side&, const Side&) = default;  // element, then face
};

struct Block {
  std::string name;
  int first_element = 0;
  int element_count = 0;
};

struct Mesh {
  std::vector<double> coordinates;  // [node][3], m
  std::vector<int> connectivity;    // [element][8]
  std::vector<Block> blocks;
  std::map<std::string, std::vector<int>> node_sets;    // sorted, unique node indices
  std::map<std::string, std::vector<Side>> side_sets;

  int node_count() const { return static_cast<int>(coordinates.size() / 3); }
  int element_count() const { return static_cast<int>(connectivity.size() / 8); }
  const Block* find_block(const std::string& name) const;
  /// The 4 global node indices of a side, counter-clockwise seen from outside.
  std::array<int, 4> side_nodes(const Side& s) const;
  /// Sorted unique nodes touched by a side set; MeshError if there is no side set `name`.
  std::vector<int> side_set_nodes(const std::string& name) const;
};

/// The axis-aligned box around the nodes, m; lo = +inf and hi = -inf on an axis with no node.
struct BoundingBox {
  std::array<double, 3> lo, hi;
};
BoundingBox bounding_box(const Mesh& mesh);

/// Append `other` to `into`, renumbering its nodes and elements. Blocks, node sets and side sets
/// keep their names; a name present in both is an error (MeshError). Nodes are not merged.
void append(Mesh& into, const Mesh& other);

/// Checks every element's Jacobian determinant at its 8 corners (and centre) and every index
/// range; throws MeshError naming the first bad element (1-based in the message, as in gmsh and
/// ParaView cell ids + 1) and `source` (file name or "generated box NAME").
void validate(const Mesh& mesh, const std::string& source);

/// Scaled Jacobian of element e: min over corners of det(J)/(|J1||J2||J3|), 1 for a cube,
/// <= 0 for an inverted corner.
double scaled_jacobian(const Mesh& mesh, int element);

}  // namespace tribex::mesh
