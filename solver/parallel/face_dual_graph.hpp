// SPDX-License-Identifier: MIT
// The element dual graph of a mesh held in slabs (element_slab.hpp), built by all the ranks together:
// two hex8 elements are neighbours when they share a face (the graph METIS_MeshToDual makes with 4
// common nodes on rank 0, parallel/partition.cpp), so that no rank needs the whole mesh.
//
// Each face is keyed by its 4 node numbers sorted ascending; a face's key decides the rank that
// matches it (the home of its smallest node in the even split of the node numbers), so both elements of
// an inner face meet on one rank whichever slabs hold them: one sparse exchange (sparse_exchange.hpp)
// sends every rank the (key, element) records bound for it, and a second returns each matched pair to the ranks whose slabs hold its elements. Per element
// 6 records of 20 B go out, packed straight into one send buffer (freed after the exchange), and a rank's
// share of the faces comes in and is sorted in place: about 240 B per element of the slab at the peak
// (rank 0 measured 62 MB above its level for a slab of 252,250 elements: docs/measurements/2026-11-29-ptscotch-partition.md).
#pragma once

#include <vector>

#include "solver/parallel/element_slab.hpp"

namespace tribex::solver::parallel {

/// This rank's rows of the distributed graph, CSR: the neighbours of local element e (global element
/// e + vertex_offset[rank]) are neighbour[offset[e] .. offset[e + 1]), global element numbers ascending,
/// each once, no self loops; vertex_offset [rank + 1] is the slabs' first elements (slab_offsets'
/// layout, gathered from the slabs themselves).
struct DualGraphRows {
  std::vector<int> vertex_offset;
  std::vector<int> offset, neighbour;
};

/// Collective over MPI_COMM_WORLD (every rank passes its slab; a rank may hold none). A face in three
/// or more elements (a non-manifold mesh) links each pair of them. Without MPI: one rank, no messages.
DualGraphRows face_dual_graph(const ElementSlab& slab);

}  // namespace tribex::solver::parallel
