// SPDX-License-Identifier: MIT
// Node-to-face enforcement (steps 2-5 of a pass, contact_manager.hpp): each slave node is projected
// on its master face, penetrating nodes get the penalty force, and the interaction law's hooks add
// the rest (laws/contact_law.hpp). The law is visited once per pass; the loop is a template on it.
#include <algorithm>
#include <cmath>

#include "contact/contact_manager.hpp"
#include "contact/geometry/axis_distance.hpp"
#include "contact/node_to_face/closest_face.hpp"

namespace tribex::contact {

void ContactManager::node_to_face(Pass& p, const StepInputs& in, ContactTotals& totals, double friction[3]) {
  std::visit([&](const auto& law) { node_to_face_with(law, p, in, totals, friction); }, p.law);
}

template <class Law>
void ContactManager::node_to_face_with(const Law& law, Pass& p, const StepInputs& in, ContactTotals& totals,
                                       double friction[3]) {
  const ContactSurface& slave = surfaces_[p.slave];
  const ContactSurface& master = surfaces_[p.master];
  PassView view{slave,    master,         in.x,         in.v,     in.other_force, in.dt,   mass_, prescribed_,
                in.force, traction_.data(), status_.data(), totals, friction,     p.factor, p.primary,
                p.margin, axis_,          p.pairs,      master_share_, p.gap,     p.law_state.data(), p.stable_dt,
                counted_.empty() ? nullptr : counted_.data(), &uncounted_,
                completed_.empty() ? nullptr : reductions_, completed_.data()};
  constexpr bool has_point_hook = requires(ContactPoint& q) { law.at_point(q, view); };
  constexpr bool area_from_shares = requires { Law::area_from_shares; };
  p.face_bounds.next_step();
  for (int k = 0; k < slave.node_count(); ++k) {
    const int count = p.candidate_offset[k + 1] - p.candidate_offset[k];
    if (count == 0) continue;
    const int node = slave.nodes[k];
    const double* xs = in.x + 3 * node;
    const BestFace best = closest_face(in.x, master, &p.candidates[p.candidate_offset[k]], count, xs, p.last_face[k],
                                       &p.face_bounds, p.nearest_face[k]);
    p.last_face[k] = best.face >= 0 && best.proj.interior ? best.face : -1;
    p.nearest_face[k] = best.face;
    if (best.usable) p.gap[k] = best.proj.gap;
    if (owner_computes_ && !view.counts(node)) continue;  // another rank's node: its gap only (edge radius)
    ContactPoint point{k, node, best.face, &master.face_nodes[4 * std::max(best.face, 0)], best.proj.shape,
                       best.proj.normal, best.proj.gap, slave.node_area[k]};
    if constexpr (!Law::penalty) {
      // The law is the whole normal contact; a node deeper than the margin is the far side.
      if (best.usable && -best.proj.gap <= p.margin) law.at_point(point, view);
      continue;
    } else {
      if constexpr (has_point_hook) {
        if (best.usable && best.proj.gap >= 0.0) {
          law.at_point(point, view);
          continue;
        }
      }
      if (!best.usable || best.proj.gap >= 0.0) continue;
      // A node deeper than the search margin is not a contact but the far side of a thin body.
      if (-best.proj.gap > p.margin) continue;
      const double kp = penalty_stiffness(p.penalty_scale, point);
      // f_s = -k_p g n (g < 0 pushes the slave node out along the master's outward normal).
      const double fn_mag = -kp * best.proj.gap * p.factor;
      const double* n = best.proj.normal;
      // force direction = axis: the linear (small-slope) contact of the half-space theories (Hertz, the
      // layered continuum of tools/layered) puts the traction along the flat's normal; on a curved master
      // the face normal tilts by r/R and adds a radial traction p r/R that shears a soft slave layer outward
      // (verification/coated/README.md "Cases 4 and 5"). The gap stays the normal projection (O((r/R)^2) apart).
      double along_axis[3];
      if (p.force_along_axis && axis_.set) {
        const double* d = axis_.direction;
        const double sign = n[0] * d[0] + n[1] * d[1] + n[2] * d[2] < 0.0 ? -1.0 : 1.0;
        for (int i = 0; i < 3; ++i) along_axis[i] = sign * d[i];
        n = along_axis;
      }
      for (int i = 0; i < 3; ++i) {
        in.force[3 * node + i] += fn_mag * n[i];
        for (int a = 0; a < 4; ++a) in.force[3 * point.face_nodes[a] + i] -= best.proj.shape[a] * fn_mag * n[i];
        traction_[3 * node + i] += fn_mag * n[i] / point.area;
      }
      status_[node] = 1.0;
      ContactTotals& t = view.totals_of(node);
      t.normal_force += fn_mag;
      t.compressive_force += fn_mag;
      if constexpr (!area_from_shares) t.area += p.factor * point.area;
      t.max_penetration = std::max(t.max_penetration, -best.proj.gap);
      note_penetration(t, -best.proj.gap, point.area, node);
      if (p.primary) ++t.nodes;
      if (axis_.set) {
        const double r2 = axis_distance_squared(xs, axis_.point, axis_.direction);
        t.radius_max = std::max(t.radius_max, std::sqrt(r2));
        if (p.primary && view.counts(node)) {
          const double pressure = fn_mag / (p.factor * point.area);
          fit_r2_.push_back(r2);
          fit_p2_.push_back(pressure * pressure);
        }
      }
      if constexpr (has_point_hook) {
        point.normal_force = fn_mag;
        law.at_point(point, view);
      }
    }
  }
  if constexpr (requires { law.end_pass(view); }) law.end_pass(view);
}

}  // namespace tribex::contact
