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

/// Builds the manager; `dt` is the run's time step (scale factor x stable estimate, capped by the
/// maximum time step). Throws SetupError for a side set missing from the mesh (deck line + names)
/// or an initial overlap beyond the tolerance (the worst nodes named). Choices that run but are known
/// to be unsafe (an adhesion cut-off that drops more than 1 % of W, one-point elements under
/// node-to-face penalty contact) go to `findings`.
std::unique_ptr<contact::ContactManager> build_contact(const inputs::ContactSpec& spec, const Model& model, double dt,
                                                       std::vector<std::string>* report,
                                                       SetupFindings* findings = nullptr);

}  // namespace tribex::solver
