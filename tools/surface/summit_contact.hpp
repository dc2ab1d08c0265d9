// SPDX-License-Identifier: MIT
// Discrete GW over the summits found on a height map (report Eq. 4.2; docs/theory.md 10.5), with DMT
// adhesion per contacting asperity (Eq. 4.11): a rigid flat at height h above the map mean touches
// every summit i with w_i = z_i - h > 0, each of its own radius R_i = 1/kappa_i:
//   P(h) = sum_i (4/3) E* sqrt(R_i) w_i^{3/2}  [ - 2 pi W R_i for DMT ],   A(h) = sum_i pi R_i w_i.
// Neighbouring asperities do not interact (the GW assumption).
#pragma once

#include <vector>

#include "tools/surface/spectral_moments.hpp"

namespace tribex::surface {

struct SummitContact {
  double h = 0.0;           // flat height above the mean plane, m
  std::size_t contacts = 0;
  double area = 0.0;        // true contact area, m^2
  double load_hertz = 0.0;  // N
  double load_dmt = 0.0;    // N (applied load with adhesion)
};

/// Summits with non-positive curvature (flat plateaus) are skipped: they have no finite radius.
SummitContact summit_contact(const std::vector<Summit>& summits, double e_star, double work_of_adhesion, double h);

}  // namespace tribex::surface
