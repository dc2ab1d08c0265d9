// SPDX-License-Identifier: MIT
// Element partition of a mesh for a parallel run (rank 0 computes it and sends the ranks their parts:
// parallel/mesh_part.hpp), by the deck's `begin decomposition` method:
//   - metis (default): METIS k-way (METIS_PartGraphKway) on the element dual graph (two hex8 elements
//     are neighbours when they share a face, 4 nodes), or for a large mesh on the graph of compact
//     clusters of elements (element_clusters.hpp), with a fixed seed so that a run is partitioned the
//     same way every time;
//   - rcb: recursive coordinate bisection of the element centroids (equal element counts; each box's
//     longest side after the `coordinate scale` cut at its median). Planar cuts the user can steer: a
//     contact zone that travels along y stays shared by the ranks when y's scale is small, since no
//     cut then crosses the track (inputs/examples/afm_sliding).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "solver/parallel/coordinate_split.hpp"

namespace tribex::solver::parallel {

/// [element] the part (rank) that owns it, in [0, parts). One part: all zeros (METIS not called).
/// `cluster_size`: partition the graph of clusters of at most this many elements
/// (element_clusters.hpp) instead of the element graph; 0 chooses: the element graph up to 262,144
/// elements, above it clusters sized for a graph of about 65,536 vertices (at least 16 per part), so
/// that METIS's workspace on rank 0 stays small. The contact surfaces are placed afterwards
/// (place_contact_patches, solver/parallel/contact_partition.hpp). Throws std::runtime_error when METIS fails.
std::vector<int> partition_elements(const mesh::Mesh& mesh, int parts, int cluster_size = 0);
/// [element] the part by recursive coordinate bisection of the element centroids, sides compared after
/// `scale`. One part: all zeros. Deterministic. Throws std::runtime_error for more parts than elements.
std::vector<int> partition_elements_rcb(const mesh::Mesh& mesh, int parts, const AxisScale& scale = kUnitScale);
/// The cluster size partition_elements chooses for `elements` and `parts` (1: the element graph).
int partition_cluster_size(int elements, int parts);

}  // namespace tribex::solver::parallel
