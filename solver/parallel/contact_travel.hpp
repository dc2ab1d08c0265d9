// SPDX-License-Identifier: MIT
// Which way the contact zone travels in a run, read from the deck before the run, so that a parallel
// run's cuts can follow it without the user's `coordinate scale` (inputs/examples/afm_sliding: a tip
// sliding 200 nm along y over a track; cuts across y would hand the whole zone from rank to rank as it
// slides, cuts along y keep it shared all the way).
//
// The travel: among the prescribed displacements and velocities of the region that move a body holding
// a contact surface (a node of the node set and a face of the surface in one connected piece of the
// mesh), the component, other than the contact normal, along which the prescribed motion covers the
// longest distance over the run (the total variation of u_c(t) from the start to the termination time;
// for a velocity, the integral of |v_c(t)|). The contact normal is the dominant component of the
// summed area vectors of the contact surface whose faces sum to the largest one (a flat track: its
// normal; a closed body sums to zero and decides nothing). An approach along the normal is not travel;
// initial velocities and prescribed forces are not counted (the distance they give is not known before
// the run).
//
// A zone travels across the partition only when the distance exceeds the width of a patch along the
// path: the extent of the smallest contact surface along the axis (the smaller body's footprint holds
// the zone) over the number of ranks. A 200 nm slider slid 2 nm and back (tests/parallel's strips)
// stays on its patches, and cuts along its path would only lengthen every rank's band of ghosts (at
// 4 ranks the regions grew from about 200 of the 564 faces to 250-564).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "inputs/deck.hpp"
#include "mesh/generated_plan.hpp"
#include "mesh/mesh.hpp"
#include "solver/parallel/coordinate_split.hpp"

namespace tribex::solver {

struct ContactTravel {
  int axis = 0;              // 0, 1, 2: x, y, z
  double distance = 0.0;     // m, the total variation of the prescribed motion along `axis`
  std::string node_set;      // the motion's node set
  int normal_axis = -1;      // the contact normal's dominant component; -1 where the surfaces decide none
  double zone_extent = 0.0;  // m, the smallest contact surface's extent along `axis`
};

/// The travel of `deck`'s contact zone on `mesh` (the whole mesh), or nullopt: no contact definition,
/// or no prescribed motion of a contact body along a tangential component over the run.
std::optional<ContactTravel> contact_travel(const inputs::Deck& deck, const mesh::Mesh& mesh);
/// The same from a generated mesh's plan (mesh/generated_plan.hpp; `set-up = distributed`): the connected
/// pieces are the plan's grids, the surfaces' faces those of their elements built alone. Every rank alike.
std::optional<ContactTravel> contact_travel(const inputs::Deck& deck, const mesh::GeneratedPlan& plan);
/// The same as if the mesh were one connected piece, from `surfaces` (a mesh holding the contact surfaces'
/// elements and their side sets whole) and the names of the mesh's node sets: every prescribed motion of a
/// node set counts as moving a contact body, so none means contact_travel finds none on the whole mesh, and
/// one means it may (an Exodus file read in slices has no connected pieces: the set-up falls back then).
std::optional<ContactTravel> contact_travel_one_piece(const inputs::Deck& deck, const mesh::Mesh& surfaces,
                                                      const std::vector<std::string>& node_sets);

/// Whether `travel` carries the zone beyond a patch's width at `parts` ranks: distance > zone_extent / parts.
bool crosses_patches(const ContactTravel& travel, int parts);

/// The coordinate scale of the partition's cuts into `parts`: the deck's `coordinate scale` where it
/// gives one; else kTravelScale on the travel's axis where it crosses the patches (so that the longest
/// side of every box the bisections compare lies across the path: the cuts run along it unless a box
/// is more than 1 / kTravelScale times longer along the path than across it); else 1 1 1.
parallel::AxisScale decomposition_scale(const inputs::DecompositionSpec& spec, const std::optional<ContactTravel>& travel,
                                        int parts);

inline constexpr double kTravelScale = 0.01;

}  // namespace tribex::solver
