// SPDX-License-Identifier: MIT
// The contact's result fields beside the traction and status it keeps each step (contact_manager.hpp):
// the normal contact pressure and the gap of the slave nodes, computed only when a field output asks
// for them (docs/theory.md 12.1).
#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/contact_manager.hpp"

namespace tribex::contact {

void ContactManager::normal_pressure(const double* x, std::vector<double>& out) const {
  out.assign(status_.size(), 0.0);
  std::vector<double> normal(3 * status_.size(), 0.0);
  // [node] the partition factor of its slave passes (0: no slave node): a symmetric interaction's
  // pass adds 1/2 of its forces (docs/theory.md 5.1), the pressure is that of the whole contact.
  std::vector<double> factor(status_.size(), 0.0);
  for (const auto& p : passes_) {
    const ContactSurface& s = surfaces_[p.slave];
    for (int node : s.nodes) factor[node] = factor[node] > 0.0 ? std::min(factor[node], p.factor) : p.factor;
    for (int f = 0; f < s.face_count(); ++f) {
      const int* n = &s.face_nodes[4 * f];
      if (!present_.empty() && !(present_[n[0]] && present_[n[1]] && present_[n[2]] && present_[n[3]])) continue;
      // Area vector a = (d1 x d2) / 2 of the quad (outward: counter-clockwise seen from outside).
      double d1[3], d2[3];
      for (int i = 0; i < 3; ++i) {
        d1[i] = x[3 * n[2] + i] - x[3 * n[0] + i];
        d2[i] = x[3 * n[3] + i] - x[3 * n[1] + i];
      }
      const double a[3] = {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]), 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                           0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
      for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 3; ++i) normal[3 * n[c] + i] += a[i];
    }
  }
  // p = -t . n / (|n| factor) (docs/theory.md eq. 12.2).
  for (std::size_t node = 0; node < status_.size(); ++node) {
    const double* n = &normal[3 * node];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(factor[node] > 0.0) || !(length > 0.0)) continue;
    const double* t = &traction_[3 * node];
    out[node] = -(t[0] * n[0] + t[1] * n[1] + t[2] * n[2]) / (length * factor[node]);
  }
}

// g = (x_s - x_m) . n_m of each slave pass (docs/theory.md eq. 12.3), the smallest per node.
void ContactManager::node_gaps(std::vector<double>& out) const {
  out.assign(status_.size(), std::numeric_limits<double>::quiet_NaN());
  for (const auto& p : passes_) {
    const ContactSurface& s = surfaces_[p.slave];
    for (int k = 0; k < s.node_count() && k < static_cast<int>(p.gap.size()); ++k) {
      const double g = p.gap[k];
      double& o = out[s.nodes[k]];
      if (std::isfinite(g) && !(o <= g)) o = g;  // the smallest over the passes; NaN stays until a gap comes
    }
  }
}

}  // namespace tribex::contact
