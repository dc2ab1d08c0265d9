// SPDX-License-Identifier: MIT
// One spherical asperity of radius R pressed w into a flat (report Eqs. 4.4 and 4.10; docs/theory.md
// 10.3-10.5): the Hertz force, contact area and stiffness, and the DMT pull 2 pi W R it adds while in
// contact. The one place these are written: the discrete rough-surface law in the solver
// (contact/models/rough_surface.cpp) and `tribex surface` (tools/surface/summit_contact.cpp) both sum
// them over their summits.
#pragma once

#include <cmath>

namespace tribex::gw {

struct AsperityContact {
  double area = 0.0;       // pi R w, m^2
  double force = 0.0;      // Hertz (4/3) E* sqrt(R) w^{3/2}, N
  double stiffness = 0.0;  // dP/dw = 2 E* sqrt(R w), N/m
  double pull = 0.0;       // DMT adhesive force 2 pi W R, N (to be subtracted from the load)
};

/// w > 0 (overlap, m), r > 0 (radius, m), e_star (composite modulus, Pa), work_of_adhesion (J/m^2).
inline AsperityContact asperity_contact(double w, double r, double e_star, double work_of_adhesion) {
  return {M_PI * r * w, (4.0 / 3.0) * e_star * std::sqrt(r) * w * std::sqrt(w), 2.0 * e_star * std::sqrt(r * w),
          2.0 * M_PI * work_of_adhesion * r};
}

}  // namespace tribex::gw
