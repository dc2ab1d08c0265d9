// SPDX-License-Identifier: MIT
// The hex8 of one cell of a structured grid, for the generators (box.cpp's add_grid) and the per-rank
// plan (generated_plan.cpp), which must number every element's nodes alike.
#pragma once

namespace tribex::mesh {

/// The 8 nodes of grid cell (i, j, k) in hex8 order (mesh.hpp): the bottom face at k counter-clockwise
/// seen from +z, starting at (i, j), then the top face at k + 1 above it; node(a, b, c) numbers grid node
/// (a, b, c).
template <class Index, class NodeOf>
inline void grid_cell_nodes(const NodeOf& node, Index i, Index j, Index k, int* c) {
  c[0] = node(i, j, k);
  c[1] = node(i + 1, j, k);
  c[2] = node(i + 1, j + 1, k);
  c[3] = node(i, j + 1, k);
  c[4] = node(i, j, k + 1);
  c[5] = node(i + 1, j, k + 1);
  c[6] = node(i + 1, j + 1, k + 1);
  c[7] = node(i, j + 1, k + 1);
}

}  // namespace tribex::mesh
