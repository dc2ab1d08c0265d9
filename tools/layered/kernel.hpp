// SPDX-License-Identifier: MIT
// The surface compliance of a layer stack in Hankel space (docs/theory.md 11.4.1): a normal surface
// pressure p(r) with zero shear, Hankel transform p^(xi) = int_0^inf p(r) J0(xi r) r dr, gives the
// surface deflection u_z^(xi) = 2 C(xi) p^(xi)/xi, so C = 1/E* for a homogeneous half-space
// (Boussinesq). C(xi) is found from the layers' exact solutions (the Burmister / Chen & Engel
// transfer-matrix problem), solved as one small linear system per xi with exponentials normalised
// so that none grows: stable for any xi h.
#pragma once

#include "tools/layered/stack.hpp"

namespace tribex::layered {

/// C(xi) in 1/Pa for xi >= 0 (1/m). At xi = 0: the base's 1/E* (0 for a rigid base).
double surface_compliance(const Stack& stack, double xi);

/// Closed form for one layer (h, E, nu) bonded to a rigid base (docs/theory.md 11.4.1, Eq. 11.4.5):
/// C = (1/E*) (2 kappa sinh 2t - 4t)/(2 kappa cosh 2t + 1 + kappa^2 + 4t^2), t = xi h, kappa = 3 - 4 nu.
double rigid_base_layer_compliance(const Layer& layer, double xi);

}  // namespace tribex::layered
