// SPDX-License-Identifier: MIT
// The serial ends of the distributed partition in this first step (issue 57 scope 1): rank 0, which
// read or generated the whole mesh, cuts it into contiguous element slabs and sends each rank its slab
// (element_slab.hpp); after ptscotch_parts every rank sends its elements' parts back, so that rank 0
// places the contact patches and distributes the parts as with METIS (mesh_part.hpp). The graph and its
// partition are computed by all the ranks (face_dual_graph.hpp, ptscotch_partition.hpp); rank 0 holds
// 8 ints per element of its own slab and 1 int per element of the gathered parts beside the mesh.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "solver/parallel/element_slab.hpp"

namespace tribex::solver::parallel {

/// Collective over MPI_COMM_WORLD: rank 0 passes the whole mesh, the others nullptr; every rank
/// receives its slab of the even split (slab_offsets). One rank: the whole mesh's connectivity.
ElementSlab scatter_element_slabs(const mesh::Mesh* whole);

/// Collective: every rank passes [local element] the part of each element of its slab; rank 0 receives
/// [element] the part of every element of the whole mesh (the others an empty vector).
std::vector<int> gather_slab_parts(const ElementSlab& slab, const std::vector<int>& part);

/// The partition of rank 0's whole mesh into `parts` computed by all the ranks: scatter, face dual graph,
/// PT-Scotch, gather. Collective; on rank 0 [element] the part, elsewhere empty. Throws
/// std::runtime_error on every rank alike when the partition cannot be made.
std::vector<int> partition_elements_ptscotch(const mesh::Mesh* whole, int parts);

}  // namespace tribex::solver::parallel
