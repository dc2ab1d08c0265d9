// SPDX-License-Identifier: MIT
// The distributed set-up of a generated mesh (`begin decomposition` / `set-up = distributed`, issue 57
// scope 2; solver/README.md "Parallel runs"): no rank ever holds the whole mesh.
//
//   1. every rank builds the connectivity of its slab of elements from the plan (mesh/generated_plan.hpp;
//      slab_offsets' even split): 32 B per element of the slab;
//   2. the ranks partition the slabs' face dual graph together (face_dual_graph.hpp, ptscotch_parts);
//   3. one all-to-all sends each element number to its part's rank;
//   4. each rank builds its part's mesh from the plan (the coordinates with the generator's arithmetic:
//      the serial generator's values bit for bit);
//   5. the holders of each node: every rank sends its nodes to their home ranks (the even split of the
//      node numbers), each home collects the ranks holding each of its nodes (ascending) and sends every
//      holder its nodes' lists back (two all-to-alls).
// The part is distribute_mesh's for the same partition (the same local numbering, sets, holders and
// whole-mesh sizes). Every node of a generated mesh is in an element (the grids' nodes are their
// elements' corners), so node_holders' check has nothing to find here.
#pragma once

#include <vector>

#include "inputs/deck.hpp"
#include "mesh/generated_plan.hpp"
#include "solver/parallel/coordinate_split.hpp"
#include "solver/parallel/mesh_part.hpp"

namespace tribex::solver::parallel {

struct GeneratedPart {
  MeshPart part;
  long long shared_nodes = 0;  // nodes held by more than one rank, over all the ranks
};

/// Steps 1-2, collective over MPI_COMM_WORLD: [local element of this rank's slab] its part, PT-Scotch's.
/// Throws std::runtime_error on every rank alike when the partition cannot be made.
std::vector<int> generated_slab_parts(const mesh::GeneratedPlan& plan);

/// Between steps 2 and 3, collective: the contact patches of place_contact_patches (contact_partition.hpp)
/// placed on the slabs' partition, as the serial set-up places them on rank 0's whole partition. Every
/// rank gathers the parts of the contact surfaces' elements (one MPI_Allreduce over them: O(N^(2/3))),
/// builds those elements alone from the plan and runs place_contact_patches on them: the patch placement
/// reads only the surfaces' elements (their faces, centroids and facing pairs), in the same order (local
/// numbers ascend with the global ones), so every rank places them as rank 0 would on the whole mesh.
/// `enforced`: the contact with the slaves the run enforces (as_enforced); nothing without one.
void place_generated_patches(const mesh::GeneratedPlan& plan, const inputs::ContactSpec* enforced,
                             std::vector<int>& slab_part, const AxisScale& scale);

/// Steps 3-5, collective: this rank's part of the plan's mesh under `slab_part` (generated_slab_parts,
/// possibly with the contact patches placed: place_generated_patches, contact_partition.hpp).
GeneratedPart generated_part(const mesh::GeneratedPlan& plan, std::vector<int> slab_part);

}  // namespace tribex::solver::parallel
