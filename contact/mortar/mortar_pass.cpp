// SPDX-License-Identifier: MIT
// ContactManager's mortar pass (enforcement = mortar): the segment integration of
// MortarEnforcement, then the per-node bookkeeping the node-to-face path does inline (status,
// contact area, node count, penetration, radius), beside the node-to-face pass (node_to_face/).
#include <algorithm>
#include <cmath>

#include "contact/contact_manager.hpp"
#include "contact/geometry/axis_distance.hpp"

namespace tribex::contact {

void ContactManager::apply_mortar(Pass& p, const double* x, double* force, ContactTotals& totals) {
  const ContactSurface& slave = surfaces_[p.slave];
  MortarSettings settings;
  settings.factor = p.factor;
  settings.margin = p.margin;
  settings.penalty_per_area = p.penalty_per_area;
  const Adhesion* adhesion = adhesion_of(p.law);
  settings.adhesion = adhesion != nullptr;
  if (adhesion) settings.law = adhesion->lj;
  if (!counted_.empty()) settings.counted = counted_.data();
  const MortarTotals t = p.mortar->apply(x, slave, surfaces_[p.master], p.candidate_offset, p.candidates, settings,
                                         force, traction_.data());
  totals.compressive_force += t.compressive_force;
  totals.adhesive_force += t.adhesive_force;
  totals.adhesion_energy += t.adhesion_energy;
  const auto& mean_gap = p.mortar->mean_gap();
  const auto& pressure = p.mortar->pressure();
  const auto& area = p.mortar->overlap_area();
  // In contact: a penalty pressure, or (adhesion) a mean gap within the junction gap tolerance.
  const double tolerance = adhesion ? adhesion->gap_tolerance : -INFINITY;
  for (int k = 0; k < slave.node_count(); ++k) {
    p.gap[k] = mean_gap[k];
    if (!(pressure[k] > 0.0 || mean_gap[k] <= tolerance)) continue;
    const int node = slave.nodes[k];
    status_[node] = 1.0;
    if (!counts(node)) continue;
    totals.area += p.factor * area[k];
    if (p.primary) ++totals.nodes;
    totals.max_penetration = std::max(totals.max_penetration, -mean_gap[k]);
    note_penetration(totals, -mean_gap[k], slave.node_area[k], node);
    if (axis_.set) totals.radius_max = std::max(totals.radius_max, axis_distance(x + 3 * node, axis_.point, axis_.direction));
  }
}

}  // namespace tribex::contact
