// SPDX-License-Identifier: MIT
// Element-based stable time step (docs/theory.md 1.4):
//   dt_e = L_e / c_d * (sqrt(1 + xi^2) - xi),  L_e = V / sqrt(2 B_iI B_iI),  xi = b1 (linear bulk
//   viscosity as a fraction of critical damping of the highest mode),  c_d = sqrt(M(J) / rho(J)),
// evaluated on the current configuration x = X + u with the tangent dilatational modulus M; the
// current gradient operator is B = cof(F) B0 with the element's mean F (exact for an affine
// deformation of the element), so the estimate costs about one extra gradient per element.
// Penalty-free problems have no nodal contribution beyond the elements; silent-boundary dashpots
// and mass damping are integrated semi-implicitly and do not restrict the step.
#pragma once

#include "solver/model.hpp"

namespace tribex::solver {

struct StableStep {
  double dt = 0.0;           // min over elements of dt_e (before the scale factor), s
  int controlling_element = -1;  // global element index (0-based)
  int inverted_element = -1;     // first element with non-positive volume, or -1
};

/// `u` is the displacement [node][3] (nullptr: reference configuration). `per_element` (optional,
/// [element], global numbering) receives every element's dt_e (mass scaling's set-up); the density is
/// the block's times the element's mass-scaling factor (ElementBlock::mass_scale).
StableStep compute_stable_time_step(const Model& model, const double* u, double* per_element = nullptr);

/// The same in the reference configuration over the whole model: in a parallel run the minimum over
/// the ranks (collective), the controlling element in the whole mesh's numbering (ties to the lowest).
/// `per_element` gets this rank's elements, in its local numbering.
StableStep whole_model_stable_time_step(const Model& model, double* per_element = nullptr);

}  // namespace tribex::solver
