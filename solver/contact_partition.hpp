// SPDX-License-Identifier: MIT
// What the partition of a parallel run needs from the contact definition (parallel/partition.hpp):
// the elements under each contact surface, which every rank should hold an equal share of, and
// links between the elements of facing slave and master faces, which the partition should keep on
// one rank, so that a rank's slave nodes find their master faces at home and its contact ghosts
// are the band around its patch of the zone, not the whole patch (tools/bench/README.md "Counts per rank").
#pragma once

#include <vector>

#include "inputs/deck.hpp"
#include "mesh/mesh.hpp"

namespace tribex::solver {

/// [surface][element] 1 for the elements with a face in each contact surface of `spec` (none: empty).
std::vector<std::vector<char>> contact_surface_elements(const mesh::Mesh& mesh, const inputs::ContactSpec* spec);

/// Pairs of elements [link][2] facing each other across an interaction in the reference positions:
/// for each face of either surface, the element of the nearest face of the other surface whose
/// centroid lies within twice the larger of the two faces' diameters. Each pair once, the smaller
/// element first, ascending; none without `spec`. Side sets missing from the mesh are skipped
/// (build_contact reports them).
std::vector<int> contact_element_links(const mesh::Mesh& mesh, const inputs::ContactSpec* spec);

}  // namespace tribex::solver
