// SPDX-License-Identifier: MIT
// Energy bookkeeping (docs/theory.md 1.3; docs/conventions.md B.3 "Energy balance"). All in J.
#pragma once

#include <algorithm>
#include <cmath>

namespace tribex::solver {

struct Energies {
  double kinetic = 0.0;                 // (1/2) sum m |v^n|^2
  double internal = 0.0;                // stored strain energy sum V0 W(F)
  double hourglass = 0.0;               // stored hourglass energy (stiffness form)
  double external_work = 0.0;           // work of reactions at constrained dofs and applied loads
  double silent_boundary_dissipation = 0.0;
  double damping_dissipation = 0.0;     // mass-proportional damping
  double viscous_dissipation = 0.0;     // bulk viscosity + hourglass viscosity
  double contact_work = 0.0;            // filled by contact (later issues)
  double plastic_dissipation = 0.0;     // work of the material updates (J2 plasticity), sum V0 sigma:deps_p
  double initial = 0.0;                 // kinetic + internal at t = 0

  /// Stored + dissipated minus what was put in.
  double balance() const {
    return kinetic + internal + hourglass + silent_boundary_dissipation + damping_dissipation +
           viscous_dissipation + plastic_dissipation + contact_work - initial - external_work;
  }
  /// |balance| relative to the largest energy magnitude of the run so far.
  double relative_error() const {
    const double scale = std::max({std::abs(initial) + std::abs(external_work), kinetic + internal + hourglass,
                                   silent_boundary_dissipation + damping_dissipation + viscous_dissipation +
                                       plastic_dissipation});
    return scale > 0.0 ? std::abs(balance()) / scale : 0.0;
  }
};

}  // namespace tribex::solver
