// SPDX-License-Identifier: MIT
#include "tools/surface/summit_contact.hpp"

#include "contact/rough/asperity_contact.hpp"

namespace tribex::surface {

SummitContact summit_contact(const std::vector<Summit>& summits, double e_star, double work_of_adhesion, double h) {
  SummitContact c;
  c.h = h;
  for (const auto& s : summits) {
    const double w = s.height - h;
    if (w <= 0.0 || s.curvature <= 0.0) continue;
    const auto a = gw::asperity_contact(w, 1.0 / s.curvature, e_star, work_of_adhesion);
    ++c.contacts;
    c.area += a.area;
    c.load_hertz += a.force;
    c.load_dmt += a.force - a.pull;
  }
  return c;
}

}  // namespace tribex::surface
