// SPDX-License-Identifier: MIT
// The coarse graph rank 0 partitions a large mesh on (parallel/partition.hpp): elements grouped into
// compact clusters, the leaves of a k-d tree over their centroids (split at the median of the
// longest side until a leaf holds at most `size` elements), and the clusters' adjacency weighted by
// the nodes they share. METIS's multilevel workspace grows with the graph it is given (about 170 MB
// for the dual graph of 1 M hex8 with three constraints); on clusters of 16 elements it is a
// few MB, and building the clusters takes 20 B per element and 4 B per node, so rank 0's set-up peak
// stays near the whole mesh itself (docs/measurements/2026-11-26-bench-rank-counts.md "Rank 0's set-up,
// contact patches, positions-only ghost rows").
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::solver::parallel {

struct ElementClusters {
  int count = 0;
  std::vector<int> of_element;  // [element] its cluster; clusters numbered in k-d tree order
  // The cluster graph, CSR, both directions, no self loops: clusters are neighbours when an element
  // of one reaches a node first reached by an element of the other (every shared face; some clusters
  // touching only along an edge or at a corner are missed, where a third cluster reached the nodes
  // first, which the partition does not need); the weight counts the element-node incidences that
  // reach such nodes (about 4 per shared face).
  std::vector<int> offset, neighbour, weight;
};

/// Clusters of at most `size` (>= 1) elements, deterministic for a given mesh.
ElementClusters cluster_elements(const mesh::Mesh& mesh, int size);

}  // namespace tribex::solver::parallel
