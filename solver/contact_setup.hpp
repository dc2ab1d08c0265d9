// SPDX-License-Identifier: MIT
// From the deck's contact definition to a contact::ContactManager: surfaces from side sets,
// interactions, the penalty reference time step, and the pre-flight check of initial overlaps.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact/contact_manager.hpp"
#include "inputs/deck.hpp"
#include "solver/guards/run_warning.hpp"

namespace tribex::solver {

struct Model;

/// What the contact set-up reads besides the model's blocks, in global node and element numbering:
/// in a serial run the model's own mesh, masses and constraints; in a parallel run the contact
/// surfaces' elements (contact_surface_mesh of the whole mesh, the same on every rank) and the
/// surface nodes' masses and constraints gathered from their owners (solver/README.md "Parallel runs").
struct ContactGeometry {
  const mesh::Mesh& mesh;            // its blocks are the model's, in the same order
  const std::vector<double>& mass;   // [global node] lumped mass (the surface nodes at least)
  std::vector<char> prescribed;      // [global node] 1 where all three velocity components are prescribed
};

/// The elements of `whole` that have a face in a contact surface's side set, in global node
/// numbering (coordinates kept for those elements' nodes only); every block and side set by name.
mesh::Mesh contact_surface_mesh(const mesh::Mesh& whole, const inputs::ContactSpec& spec);

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
