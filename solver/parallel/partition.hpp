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
/// Throws std::runtime_error when METIS fails.
std::vector<int> partition_elements(const mesh::Mesh& mesh, int parts);

}  // namespace tribex::solver::parallel
