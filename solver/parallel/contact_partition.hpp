// SPDX-License-Identifier: MIT
// Where the contact zone goes in a parallel run's partition (parallel/partition.hpp makes the
// partition of the volume): after METIS, the elements of the contact surfaces are placed in compact
// patches, one per rank, so that a small contact zone is shared by all the ranks (the contact work
// per rank falls as 1/N) and each rank's ghosts are the band around its patch (the contact bytes per
// rank fall with the patch's perimeter): tools/bench/README.md "Counts per rank".
//   - the elements with a face in a slave surface of an interaction (both surfaces of a symmetric
//     one; the slave the run enforces: callers pass as_enforced(spec), contact_setup.hpp, since
//     build_contact swaps a stiff slave on a soft master) are cut into `parts` patches by the planes of
//     a recursive coordinate bisection of the face centroids of each interaction's *smaller* surface
//     (the diagonal of its centroid box, after the deck's `coordinate scale`; ties: the slave): equal
//     counts of those faces, each box cut midway between its halves across the longest side of the
//     part of it the slave elements' box overlaps, so a tall tip is cut across the track, not along its
//     height (parallel/coordinate_split.hpp bisect_like). The contact zone lies within the smaller body's
//     footprint, so the planes through it share the zone evenly; a track's own median would follow the
//     coarse faces beside the track (inputs/examples/afm_sliding case (b): 59/41 of the pairs);
//   - patch k goes to the rank whose METIS part holds most of its elements (greedy, largest overlap
//     first), so that few elements move;
//   - each element of a master surface facing a slave face (the nearest within two face diagonals,
//     contact_element_links) goes with that slave element, so that a rank's slave nodes find their
//     master faces at home; master elements facing none keep their METIS part.
// A surface layer placed on another rank than the volume under it adds its inner nodes to the halo
// (24 B each and step): about the zone's nodes in all, small against the halo of the volume.
#pragma once

#include <vector>

#include "inputs/deck.hpp"
#include "mesh/mesh.hpp"
#include "solver/parallel/coordinate_split.hpp"

namespace tribex::solver {

/// Pairs of elements [link][2] = (slave side, master side) facing each other across an interaction in
/// the reference positions: for each face of either surface, the element of the nearest face of the
/// other surface whose centroid lies within twice the larger of the two faces' diameters. Each pair
/// once, ascending; none without `spec`. Side sets missing from the mesh are skipped (build_contact
/// reports them).
std::vector<int> contact_element_links(const mesh::Mesh& mesh, const inputs::ContactSpec* spec);

/// Places the contact surfaces' elements of `part` [element] (a partition into `parts`) in patches as
/// above, the sides of the bisection's boxes compared after `scale`. Nothing without `spec` or with one
/// part. Deterministic.
void place_contact_patches(const mesh::Mesh& mesh, const inputs::ContactSpec* spec, int parts, std::vector<int>& part,
                           const parallel::AxisScale& scale = parallel::kUnitScale);

}  // namespace tribex::solver
