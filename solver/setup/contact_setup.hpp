// SPDX-License-Identifier: MIT
// From the deck's contact definition to a contact::ContactManager: surfaces from side sets,
// interactions, the penalty reference time step, and the pre-flight check of initial overlaps.
#pragma once

#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "contact/contact_manager.hpp"
#include "inputs/deck.hpp"
#include "mesh/generated_plan.hpp"
#include "solver/guards/run_warning.hpp"

namespace tribex::solver {

struct Model;

/// The contact surfaces in the contact's own numbering (the same in serial and parallel runs, and on
/// every rank): the nodes on the faces of the side sets a contact definition names, numbered by
/// ascending whole-mesh node. The contact arrays (positions, forces, tractions, restart state) are
/// sized by these surface nodes, not by the mesh (solver/README.md "Parallel runs").
struct ContactFaces {
  std::vector<int> global_node;                        // [surface node] the whole mesh's node, ascending
  std::vector<double> coordinates;                     // [surface node][3], m
  std::map<std::string, std::vector<int>> face_nodes;  // side set -> [face][4] surface nodes (every side set
                                                       // of the mesh by name; faces only for the contact's)
  std::map<std::string, std::vector<int>> face_block;  // side set -> [face] block index (the mesh's block order)
};

/// The contact faces of `mesh` (the whole mesh: a serial run's, or rank 0's in a parallel run).
ContactFaces contact_faces(const mesh::Mesh& mesh, const inputs::ContactSpec& spec);
/// The same of a generated mesh's plan (mesh/generated_plan.hpp), from the elements of the contact's side
/// sets alone: every rank of a distributed set-up makes its own (`set-up = distributed`).
ContactFaces contact_faces(const mesh::GeneratedPlan& plan, const inputs::ContactSpec& spec);

/// Whether the run enforces interaction `it` with its surfaces swapped: a one-pass node-to-face
/// penalty pair whose slave is more than twice as stiff (mean P-wave modulus of the elements under its
/// faces) as its master (a soft master folds under the slave's point loads: contact/README.md "Node to
/// face on a soft master"); build_contact swaps them and logs it. `block_modulus` [block] the P-wave
/// modulus of each block's material, Pa, in the mesh's block order (ContactFaces::face_block's).
bool runs_swapped(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec, const ContactFaces& faces,
                  std::span<const double> block_modulus);

/// `spec` with each interaction's surfaces in the order the run enforces them (runs_swapped): what
/// the partition places (place_contact_patches puts the slave surfaces in patches).
inputs::ContactSpec as_enforced(inputs::ContactSpec spec, const ContactFaces& faces, std::span<const double> block_modulus);

/// Collective: rank 0's `faces` on every rank.
void broadcast_contact_faces(ContactFaces& faces);

/// What the contact set-up reads besides the model's blocks: the faces and, per surface node, the
/// lumped mass and whether all three velocity components are prescribed (summed from the nodes'
/// owners in a parallel run).
struct ContactGeometry {
  const ContactFaces& faces;
  const std::vector<double>& mass;  // [surface node] kg
  std::vector<char> prescribed;     // [surface node]
};

/// Builds the manager; `dt` is the run's time step (scale factor x stable estimate, capped by the
/// maximum time step). Throws SetupError for a side set missing from the mesh (deck line + names)
/// or an initial overlap beyond the tolerance (the worst nodes named). Choices that run but are known
/// to be unsafe (an adhesion cut-off that drops more than 1 % of W, one-point elements under
/// node-to-face penalty contact) go to `findings`.
std::unique_ptr<contact::ContactManager> build_contact(const inputs::ContactSpec& spec, const Model& model,
                                                       const ContactGeometry& geometry, double dt,
                                                       std::vector<std::string>* report,
                                                       SetupFindings* findings = nullptr);

}  // namespace tribex::solver
