// SPDX-License-Identifier: MIT
#include "tools/surface/summit_contact.hpp"

#include <cmath>

namespace tribex::surface {

SummitContact summit_contact(const std::vector<Summit>& summits, double e_star, double work_of_adhesion, double h) {
  SummitContact c;
  c.h = h;
  for (const auto& s : summits) {
    const double w = s.height - h;
    if (w <= 0.0 || s.curvature <= 0.0) continue;
    const double r = 1.0 / s.curvature;
    const double hertz = (4.0 / 3.0) * e_star * std::sqrt(r) * w * std::sqrt(w);  // Eq. 4.4
    ++c.contacts;
    c.area += M_PI * r * w;
    c.load_hertz += hertz;
    c.load_dmt += hertz - 2.0 * M_PI * work_of_adhesion * r;  // DMT pull-off force 2 pi W R per contact
  }
  return c;
}

}  // namespace tribex::surface
