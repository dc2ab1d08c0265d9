// SPDX-License-Identifier: MIT
// The distributed set-up (`begin decomposition` / `set-up = distributed`, issue 57 scope 2; solver/README.md
// "Parallel runs") of a mesh no rank holds whole, taken from an element source (element_source.hpp: a
// generated mesh's plan, or an Exodus II file read in slices): the same pipeline for both.
//
//   1. every rank takes the connectivity of its slab of elements from the source (slab_offsets' even
//      split): 32 B per element of the slab;
//   2. the ranks partition the slabs' face dual graph together (face_dual_graph.hpp, ptscotch_parts);
//   3. one all-to-all sends each element number to its part's rank;
//   4. each rank builds its part's mesh from the source (ElementSource::elements_mesh: a plan's coordinates
//      with the generator's arithmetic, a file's as read_exodus reads them: the serial values bit for bit);
//   5. the holders of each node: every rank sends its nodes to their home ranks (the even split of the
//      node numbers), each home collects the ranks holding each of its nodes (ascending) and sends every
//      holder its nodes' lists back (two all-to-alls).
// The part is distribute_mesh's for the same partition (the same local numbering, sets, holders and
// whole-mesh sizes). Every node is in an element (a grid's nodes are its elements' corners; an Exodus
// source checks it, file_slice_source.hpp), so node_holders' check has nothing to find here.
#pragma once

#include <vector>

#include "inputs/deck.hpp"
#include "solver/parallel/element_source.hpp"
#include "solver/parallel/coordinate_split.hpp"
#include "solver/parallel/mesh_part.hpp"

namespace tribex::solver::parallel {

struct SourcePart {
  MeshPart part;
  long long shared_nodes = 0;  // nodes held by more than one rank, over all the ranks
};

/// Steps 1-2, collective over MPI_COMM_WORLD: [local element of this rank's slab] its part, PT-Scotch's.
/// Throws std::runtime_error on every rank alike when the partition cannot be made.
std::vector<int> slab_parts(const ElementSource& source);

/// Between steps 2 and 3, collective: the contact patches of place_contact_patches (contact_partition.hpp)
/// placed on the slabs' partition, as the serial set-up places them on rank 0's whole partition. Every
/// rank gathers the parts of the contact surfaces' elements (one MPI_Allreduce over them: O(N^(2/3))),
/// builds those elements alone from the source and runs place_contact_patches on them: the patch placement
/// reads only the surfaces' elements (their faces, centroids and facing pairs), in the same order (local
/// numbers ascend with the global ones), so every rank places them as rank 0 would on the whole mesh.
/// `enforced`: the contact with the slaves the run enforces (as_enforced); nothing without one.
void place_source_patches(const ElementSource& source, const inputs::ContactSpec* enforced,
                          std::vector<int>& slab_part, const AxisScale& scale);

/// Steps 3-5, collective: this rank's part of the source's mesh under `slab_part` (slab_parts, possibly
/// with the contact patches placed: place_source_patches, contact_partition.hpp).
SourcePart source_part(const ElementSource& source, std::vector<int> slab_part);

/// Collective: the elements of the contact surfaces' side sets (ElementSource::side_set_elements).
std::vector<int> contact_elements(const ElementSource& source, const inputs::ContactSpec& contact);

}  // namespace tribex::solver::parallel
