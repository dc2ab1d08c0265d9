// SPDX-License-Identifier: MIT
// Element partition of a mesh for a parallel run: METIS k-way (METIS_PartGraphKway) on the
// element dual graph (two hex8 elements are neighbours when they share a face, 4 nodes), or for a
// large mesh on the graph of compact clusters of elements (element_clusters.hpp), with a
// fixed seed so that a run is partitioned the same way every time (rank 0 computes it and sends the
// ranks their parts: parallel/mesh_part.hpp).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::solver::parallel {

/// [element] the part (rank) that owns it, in [0, parts). One part: all zeros (METIS not called).
/// `cluster_size`: partition the graph of clusters of at most this many elements
/// (element_clusters.hpp) instead of the element graph; 0 chooses: the element graph up to 262,144
/// elements, above it clusters sized for a graph of about 65,536 vertices (at least 16 per part), so
/// that METIS's workspace on rank 0 stays small. The contact surfaces are placed afterwards
/// (place_contact_patches, solver/contact_partition.hpp). Throws std::runtime_error when METIS fails.
std::vector<int> partition_elements(const mesh::Mesh& mesh, int parts, int cluster_size = 0);
/// The cluster size partition_elements chooses for `elements` and `parts` (1: the element graph).
int partition_cluster_size(int elements, int parts);

}  // namespace tribex::solver::parallel
