// SPDX-License-Identifier: MIT
// Element partition of a mesh for a parallel run: METIS k-way (METIS_PartGraphKway) on the
// element dual graph (two hex8 elements are neighbours when they share a face, 4 nodes), with a
// fixed seed so that a run is partitioned the same way every time (rank 0 computes it and sends the
// ranks their parts: parallel/mesh_part.hpp).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::solver::parallel {

/// [element] the part (rank) that owns it, in [0, parts). One part: all zeros (METIS not called).
/// `balanced` [set][element] nonzero marks elements each part should hold an equal share of, besides
/// an equal share of all elements (one more METIS constraint per set): the elements under each
/// contact surface, so that a small contact zone is shared by several ranks (issue 25). A set
/// with fewer elements than parts is left out. Throws std::runtime_error when METIS fails.
std::vector<int> partition_elements(const mesh::Mesh& mesh, int parts, const std::vector<std::vector<char>>& balanced = {});

}  // namespace tribex::solver::parallel
