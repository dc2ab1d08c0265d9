// SPDX-License-Identifier: MIT
#include "contact/laws/junction.hpp"

#include <algorithm>
#include <cmath>

namespace tribex::contact {

void contact_shares(PassView& view, double gj) {
  const ContactSurface& slave = view.slave;
  std::vector<double>& share = view.pairs.share;
  std::fill(share.begin(), share.end(), 0.0);
  constexpr int n = 8;
  for (int f = 0; f < slave.face_count(); ++f) {
    const int* loc = &slave.face_local[4 * f];
    double g[4];
    int inside = 0;
    for (int a = 0; a < 4; ++a) {
      const double ga = view.gap[loc[a]];
      g[a] = std::isnan(ga) ? INFINITY : ga;
      inside += g[a] <= gj;
    }
    const double Af = slave.face_area[f];
    if (inside == 0) continue;
    if (inside == 4) {
      for (int a = 0; a < 4; ++a) share[loc[a]] += 0.25 * Af;
      continue;
    }
    const double far = view.margin;  // a finite stand-in for "no projection" in the interpolation
    for (double& ga : g) ga = std::min(ga, far);
    const double dA = Af / (n * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double xi = -1.0 + (2.0 * i + 1.0) / n, eta = -1.0 + (2.0 * j + 1.0) / n;
        const double N[4] = {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
                             0.25 * (1 - xi) * (1 + eta)};
        const double gs = N[0] * g[0] + N[1] * g[1] + N[2] * g[2] + N[3] * g[3];
        if (gs > gj) continue;
        for (int a = 0; a < 4; ++a) share[loc[a]] += N[a] * dA;
      }
  }
}

}  // namespace tribex::contact
