// SPDX-License-Identifier: MIT
// ContactManager's contact-radius estimators for history output (contact_radius_edge,
// contact_radius_pressure_fit; contact/models/README.md says which estimator each column is).
#include <algorithm>
#include <cmath>

#include "contact/contact_manager.hpp"
#include "contact/geometry/axis_distance.hpp"

namespace tribex::contact {

// Mean distance from the axis of the points where the gap changes sign along slave-face edges
// (linear interpolation of g between an edge's two nodes): the contact boundary located between
// nodes, so the radius does not jump by a node spacing when a ring of nodes enters contact.
double ContactManager::edge_radius(const Pass& p, const double* x) const {
  const ContactSurface& slave = surfaces_[p.slave];
  double sum = 0.0;
  double count = 0.0;
  for (int f = 0; f < slave.face_count(); ++f) {
    if (!counts(slave.face_nodes[4 * f])) continue;  // a face is reported by the rank counting its first node
    for (int e = 0; e < 4; ++e) {
      const int a = slave.face_nodes[4 * f + e], b = slave.face_nodes[4 * f + (e + 1) % 4];
      const double ga = p.gap[slave.face_local[4 * f + e]], gb = p.gap[slave.face_local[4 * f + (e + 1) % 4]];
      if (!(ga < 0.0 && gb >= 0.0)) continue;  // each crossing edge once: from inside to outside
      const double t = ga / (ga - gb);
      double crossing[3];
      for (int i = 0; i < 3; ++i) crossing[i] = x[3 * a + i] + t * (x[3 * b + i] - x[3 * a + i]);
      sum += axis_distance(crossing, axis_.point, axis_.direction);
      ++count;
    }
  }
  if (reductions_) {
    double both[2] = {sum, count};
    reductions_->sum(both, 2);
    sum = both[0];
    count = both[1];
  }
  return count > 0.0 ? sum / count : 0.0;
}

// Contact radius from the nodal penalty pressures p_I = f_I / A_I of the contacting slave nodes: the
// least-squares line p^2 = alpha - beta r^2 through the points (r_I^2, p_I^2), and a^2 = alpha / beta,
// the zero of the fitted p^2. Exact for the elliptic pressure p = p0 sqrt(1 - r^2/a^2) of Hertz (and
// the compressive part of DMT) contact, whatever the node positions relative to the edge; every
// contacting node contributes, so the radius does not step as a ring of nodes enters contact. It
// presumes that shape: for another pressure profile it is a shape-fitted, not a measured, radius.
// The nodal forces (not the penetrations, whose penalty stiffness varies with the projection point)
// carry the pressure. 0 with fewer than 3 nodes, all nodes at one radius, or a p^2 that does not fall with r.
// Distributed runs: each rank holds the points of the nodes it counts; the means and then the centred
// sums are summed over the ranks (two reductions), so the fit is the one-rank fit to round-off.
double ContactManager::pressure_fit_radius() const {
  const std::size_t local = fit_r2_.size();
  double moments[3] = {double(local), 0.0, 0.0};  // n, sum r^2, sum p^2
  for (std::size_t i = 0; i < local; ++i) {
    moments[1] += fit_r2_[i];
    moments[2] += fit_p2_[i];
  }
  if (reductions_) reductions_->sum(moments, 3);
  const double n = moments[0];
  if (n < 3.0) return 0.0;
  const double mean_r2 = moments[1] / n, mean_p2 = moments[2] / n;
  double sums[2] = {0.0, 0.0};  // srr, srp
  for (std::size_t i = 0; i < local; ++i) {
    sums[0] += (fit_r2_[i] - mean_r2) * (fit_r2_[i] - mean_r2);
    sums[1] += (fit_r2_[i] - mean_r2) * (fit_p2_[i] - mean_p2);
  }
  if (reductions_) reductions_->sum(sums, 2);
  const double srr = sums[0], srp = sums[1];
  // All nodes at one radius (to round-off): nothing to fit.
  if (!(srr > 1e-12 * n * mean_r2 * mean_r2) || !(srp < 0.0)) return 0.0;
  const double slope = srp / srr;  // -p0^2 / a^2
  const double a2 = mean_r2 - mean_p2 / slope;
  return a2 > 0.0 ? std::sqrt(a2) : 0.0;
}

}  // namespace tribex::contact
