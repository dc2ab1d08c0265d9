// SPDX-License-Identifier: MIT
#include "contact/contact_manager.hpp"

#include <algorithm>
#include <cmath>

#include "contact/geometry/quad_projection.hpp"

namespace tribex::contact {
namespace {

struct BestFace {
  int face = -1;
  Projection proj;
};

// 2. narrow phase: among the candidates, prefer faces over which the node projects (interior),
// then the smallest |gap|; fall back to the nearest edge/vertex point.
// `hint` (the node's face of the previous step, or -1) is tried first and kept when the node still
// projects over it: between broad-phase searches a node usually stays over the same face, and this
// skips the projections onto the other candidates (physics.md 5.1: track the current face).
BestFace closest_face(const double* x, const ContactSurface& master, const int* faces, int count, const double* p,
                      int hint = -1) {
  if (hint >= 0) {
    double X[12];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = x[3 * master.face_nodes[4 * hint + a] + i];
    const Projection pr = project_onto_quad(X, p);
    if (pr.interior) return {hint, pr};
  }
  BestFace best;
  double best_key = INFINITY;
  bool best_interior = false;
  for (int c = 0; c < count; ++c) {
    const int f = faces[c];
    double X[12];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = x[3 * master.face_nodes[4 * f + a] + i];
    const Projection pr = project_onto_quad(X, p);
    const double key = pr.interior ? std::abs(pr.gap) : pr.distance;
    if ((pr.interior && !best_interior) || (pr.interior == best_interior && key < best_key)) {
      best = {f, pr};
      best_key = key;
      best_interior = pr.interior;
    }
  }
  return best;
}

}  // namespace

ContactManager::ContactManager(std::vector<ContactSurface> surfaces, std::vector<InteractionSettings> interactions,
                               const std::vector<double>& mass, double dt_ref, int node_count)
    : surfaces_(std::move(surfaces)), mass_(mass), dt_ref_(dt_ref) {
  for (const auto& it : interactions) {
    const int order[2][2] = {{it.slave, it.master}, {it.master, it.slave}};
    for (int k = 0; k < (it.symmetric ? 2 : 1); ++k) {
      Pass p;
      p.slave = order[k][0];
      p.master = order[k][1];
      p.factor = it.symmetric ? 0.5 : 1.0;
      p.margin = it.search_margin > 0 ? it.search_margin : surfaces_[p.master].mean_edge;
      p.research_fraction = it.research_fraction;
      p.penalty_scale = it.penalty_scale;
      p.model = it.model;
      p.adhesion = it.adhesion;
      p.junction = it.junction;
      p.rough = it.rough;
      p.mean_plane_offset = it.mean_plane_offset;
      p.primary = k == 0;
      p.x_at_search.resize(3 * (surfaces_[p.slave].nodes.size() + surfaces_[p.master].nodes.size()));
      passes_.push_back(std::move(p));
    }
  }
  traction_.assign(3 * static_cast<std::size_t>(node_count), 0.0);
  status_.assign(static_cast<std::size_t>(node_count), 0.0);
  for (const auto& s : surfaces_) all_nodes_.insert(all_nodes_.end(), s.nodes.begin(), s.nodes.end());
  std::sort(all_nodes_.begin(), all_nodes_.end());
  all_nodes_.erase(std::unique(all_nodes_.begin(), all_nodes_.end()), all_nodes_.end());
}

void ContactManager::set_axis(const double point[3], const double direction[3]) {
  const double n = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (int i = 0; i < 3; ++i) {
    axis_point_[i] = point[i];
    axis_dir_[i] = direction[i] / n;
  }
  has_axis_ = true;
}

bool ContactManager::needs_search(const Pass& p, const double* x) const {
  if (!p.searched) return true;
  // Both surfaces move: a pair can close by twice the largest node motion.
  const double limit = p.research_fraction * p.margin;
  const double limit2 = limit * limit;
  std::size_t k = 0;
  for (int s : {p.slave, p.master})
    for (int node : surfaces_[s].nodes) {
      double d2 = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double d = x[3 * node + i] - p.x_at_search[3 * k + i];
        d2 += d * d;
      }
      if (d2 > limit2) return true;
      ++k;
    }
  return false;
}

void ContactManager::search(Pass& p, const double* x) {
  bucket_.find_candidates(x, surfaces_[p.slave], surfaces_[p.master], p.margin, p.candidate_offset, p.candidates);
  p.last_face.assign(surfaces_[p.slave].nodes.size(), -1);
  std::size_t k = 0;
  for (int s : {p.slave, p.master})
    for (int node : surfaces_[s].nodes) {
      for (int i = 0; i < 3; ++i) p.x_at_search[3 * k + i] = x[3 * node + i];
      ++k;
    }
  p.searched = true;
  ++total_searches_;
}

// Totals of the interface models over the passes of one step.
struct ContactManager::Accumulator {
  ContactTotals& totals;
  const double* x;
  double friction[3] = {0.0, 0.0, 0.0};  // vector sum of shear forces on the (first) slave surfaces, N
};

// Distance of x from the contact axis, for contact_radius_max.
static double axis_distance(const double* xs, const double* point, const double* dir) {
  double r[3], along = 0.0;
  for (int i = 0; i < 3; ++i) {
    r[i] = xs[i] - point[i];
    along += r[i] * dir[i];
  }
  double r2 = 0.0;
  for (int i = 0; i < 3; ++i) r2 += (r[i] - along * dir[i]) * (r[i] - along * dir[i]);
  return std::sqrt(r2);
}

// 4. interface models on slave surface node k projecting inside master face `face` with gap g:
// adhesion sigma_s(g + z0) A_I toward the master for g >= 0 (physics.md 6.2), and for the junction
// model the shear tau A_I on nodes in contact (g <= g_j; physics.md 7.1-7.2). Penalty contact
// (g < 0) has been applied and counted by the caller; here a node with 0 <= g <= g_j is counted as
// in contact (area, status, radius) as well.
void ContactManager::apply_interface(const Pass& p, int k, int face, const double* shape, const double* normal,
                                     double gap, const double* v, double* force, Accumulator& acc) {
  const ContactSurface& slave = surfaces_[p.slave];
  const ContactSurface& master = surfaces_[p.master];
  const int node = slave.nodes[k];
  const int* fn = &master.face_nodes[4 * face];
  const double area = slave.node_area[k];
  ContactTotals& totals = acc.totals;
  totals.adhesion_energy += p.factor * area * adhesive_energy(gap, p.adhesion);
  double f[3] = {0.0, 0.0, 0.0};  // force on the slave node, N
  if (gap >= 0.0) {
    // Attraction: toward the master face, i.e. against its outward normal.
    const double fa = p.factor * adhesive_traction(gap, p.adhesion) * area;
    for (int i = 0; i < 3; ++i) f[i] -= fa * normal[i];
    totals.adhesive_force += fa;
  }
  const bool in_contact = gap <= p.junction.gap_tolerance;
  if (in_contact && gap >= 0.0) {  // g < 0 was counted by the penalty branch
    status_[node] = 1.0;
    totals.area += p.factor * area;
    if (p.primary) ++totals.nodes;
    if (has_axis_) totals.radius_max = std::max(totals.radius_max, axis_distance(acc.x + 3 * node, axis_point_, axis_dir_));
  }
  if (p.model == InterfaceModel::junction && in_contact) apply_shear(p, p.junction, node, fn, shape, normal, area, v, f, acc);
  for (int i = 0; i < 3; ++i) {
    force[3 * node + i] += f[i];
    for (int a = 0; a < 4; ++a) force[3 * fn[a] + i] -= shape[a] * f[i];
    traction_[3 * node + i] += f[i] / area;
  }
}

// Junction shear tau A_I on a slave node in contact (physics.md 7.1-7.2), added to f (force on the
// slave node); v_t is the tangential part of v_slave - sum_a N_a v_a (relative to the master point).
void ContactManager::apply_shear(const Pass& p, const JunctionLaw& law, int node, const int* fn, const double* shape,
                                 const double* normal, double area, const double* v, double* f, Accumulator& acc) {
  double vr[3] = {0.0, 0.0, 0.0};
  if (v) {
    for (int i = 0; i < 3; ++i) {
      vr[i] = v[3 * node + i];
      for (int a = 0; a < 4; ++a) vr[i] -= shape[a] * v[3 * fn[a] + i];
    }
  }
  const double vn = vr[0] * normal[0] + vr[1] * normal[1] + vr[2] * normal[2];
  double vt[3], tau[3];
  for (int i = 0; i < 3; ++i) vt[i] = vr[i] - vn * normal[i];
  junction_traction(vt, law, tau);
  const double sign = p.primary ? 1.0 : -1.0;
  double power = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double ft = p.factor * tau[i] * area;
    f[i] += ft;
    acc.friction[i] += sign * ft;
    power += ft * vt[i];
  }
  acc.totals.friction_power += std::abs(power);
  acc.totals.junction_capacity += p.factor * law.strength * area;
}

// Rough-surface (GW) law on slave node k over master face `face` at gap g (models/rough_surface.hpp):
// d = g + offset; normal force p(d) A_I along the master's outward normal (p > 0 pushes apart), the
// junction shear with tau* (A_c/A_0)(d), and the node's critical step (normal spring, shear damper).
void ContactManager::apply_rough_surface(Pass& p, int k, int face, const double* shape, const double* normal,
                                         double gap, const double* v, double* force, Accumulator& acc) {
  const RoughSurfaceLaw& law = *p.rough;
  const double d = gap + p.mean_plane_offset;
  if (d >= law.contact_separation()) return;
  const ContactSurface& slave = surfaces_[p.slave];
  const int node = slave.nodes[k];
  const int* fn = &surfaces_[p.master].face_nodes[4 * face];
  const double area = slave.node_area[k];
  const RoughSurfaceState s = law.evaluate(d);
  ContactTotals& totals = acc.totals;
  const double fn_mag = p.factor * s.pressure * area;
  double f[3];
  for (int i = 0; i < 3; ++i) f[i] = fn_mag * normal[i];
  // Totals split like the other models: the Hertz (repulsive) part and the DMT pull.
  const double pull = p.factor * s.adhesion * area;
  totals.compressive_force += fn_mag + pull;
  totals.adhesive_force += pull;
  totals.nominal_area += p.factor * area;
  totals.real_area += p.factor * area * s.area_fraction;
  totals.asperity_contacts += p.factor * area * s.contact_density;
  totals.max_penetration = std::max(totals.max_penetration, -gap);
  if (s.contact_density > 0.0) {
    status_[node] = 1.0;
    totals.area += p.factor * area;
    if (p.primary) ++totals.nodes;
    if (has_axis_) totals.radius_max = std::max(totals.radius_max, axis_distance(acc.x + 3 * node, axis_point_, axis_dir_));
  }
  if (p.junction.strength > 0.0 && s.area_fraction > 0.0) {
    JunctionLaw shear = p.junction;
    shear.strength *= s.area_fraction;  // tau* A_c / A_0: junction friction on the real area
    apply_shear(p, shear, node, fn, shape, normal, area, v, f, acc);
  }
  for (int i = 0; i < 3; ++i) {
    force[3 * node + i] += f[i];
    for (int a = 0; a < 4; ++a) force[3 * fn[a] + i] -= shape[a] * f[i];
    traction_[3 * node + i] += f[i] / area;
  }
  // Explicit stability between the node and the face point (m_eff as for the penalty): the normal
  // spring k_I = A_I dp/dd needs dt < 2 sqrt(m_eff / k_I), the shear damper c_I = tau* (A_c/A_0) A_I / v_ref
  // (its slope at zero slip, physics.md 7.3) needs dt < 2 m_eff / c_I.
  const double k_spring = p.factor * s.stiffness * area;
  const double c_damper = p.factor * p.junction.strength * s.area_fraction * area / p.junction.reference_speed;
  if (k_spring > 0.0 || c_damper > 0.0) {
    double inv_mM = 0.0;
    for (int a = 0; a < 4; ++a) inv_mM += shape[a] * shape[a] / mass_[fn[a]];
    const double ms = mass_[node], mM = 1.0 / inv_mM, m_eff = ms * mM / (ms + mM);
    if (k_spring > 0.0) p.stable_dt = std::min(p.stable_dt, 2.0 * std::sqrt(m_eff / k_spring));
    if (c_damper > 0.0) p.stable_dt = std::min(p.stable_dt, 2.0 * m_eff / c_damper);
  }
}

double ContactManager::stable_time_step() const {
  double dt = INFINITY;
  for (const auto& p : passes_) dt = std::min(dt, p.stable_dt);
  return dt;
}

ContactTotals ContactManager::compute_forces(const double* x, const double* v, double* force) {
  ContactTotals totals;
  Accumulator acc{totals, x};
  for (int node : all_nodes_) {
    status_[node] = 0.0;
    traction_[3 * node] = traction_[3 * node + 1] = traction_[3 * node + 2] = 0.0;
  }
  for (auto& p : passes_) {
    if (needs_search(p, x)) {
      search(p, x);
      ++totals.searches;
    }
    const ContactSurface& slave = surfaces_[p.slave];
    const ContactSurface& master = surfaces_[p.master];
    p.gap.assign(slave.nodes.size(), NAN);
    p.stable_dt = INFINITY;
    for (int k = 0; k < slave.node_count(); ++k) {
      const int count = p.candidate_offset[k + 1] - p.candidate_offset[k];
      if (count == 0) continue;
      const int node = slave.nodes[k];
      const double* xs = x + 3 * node;
      const BestFace best = closest_face(x, master, &p.candidates[p.candidate_offset[k]], count, xs, p.last_face[k]);
      p.last_face[k] = best.face >= 0 && best.proj.interior ? best.face : -1;
      if (best.face >= 0 && best.proj.interior) p.gap[k] = best.proj.gap;
      if (p.model == InterfaceModel::rough_surface) {
        // The GW law is the whole normal contact (no penalty); a node deeper than the margin is the far side.
        if (best.face >= 0 && best.proj.interior && -best.proj.gap <= p.margin)
          apply_rough_surface(p, k, best.face, best.proj.shape, best.proj.normal, best.proj.gap, v, force, acc);
        continue;
      }
      if (p.model != InterfaceModel::frictionless && best.face >= 0 && best.proj.interior && best.proj.gap >= 0.0) {
        apply_interface(p, k, best.face, best.proj.shape, best.proj.normal, best.proj.gap, v, force, acc);
        continue;
      }
      if (best.face < 0 || !best.proj.interior || best.proj.gap >= 0.0) continue;
      // A node deeper than the search margin is not a contact but the far side of a thin body.
      if (-best.proj.gap > p.margin) continue;
      const int* fn = &master.face_nodes[4 * best.face];
      double inv_mM = 0.0;
      for (int a = 0; a < 4; ++a) inv_mM += best.proj.shape[a] * best.proj.shape[a] / mass_[fn[a]];
      const double ms = mass_[node], mM = 1.0 / inv_mM;
      const double m_eff = ms * mM / (ms + mM);
      const double kp = p.penalty_scale * m_eff / (dt_ref_ * dt_ref_);
      // f_s = -k_p g n (g < 0 pushes the slave node out along the master's outward normal).
      const double fn_mag = -kp * best.proj.gap * p.factor;
      const double* n = best.proj.normal;
      for (int i = 0; i < 3; ++i) {
        force[3 * node + i] += fn_mag * n[i];
        for (int a = 0; a < 4; ++a) force[3 * fn[a] + i] -= best.proj.shape[a] * fn_mag * n[i];
      }
      const double area = slave.node_area[k];
      for (int i = 0; i < 3; ++i) traction_[3 * node + i] += fn_mag * n[i] / area;
      status_[node] = 1.0;
      totals.normal_force += fn_mag;
      totals.compressive_force += fn_mag;
      totals.area += p.factor * area;
      totals.max_penetration = std::max(totals.max_penetration, -best.proj.gap);
      if (p.primary) ++totals.nodes;
      if (has_axis_) {
        double r[3], along = 0.0;
        for (int i = 0; i < 3; ++i) {
          r[i] = xs[i] - axis_point_[i];
          along += r[i] * axis_dir_[i];
        }
        double r2 = 0.0;
        for (int i = 0; i < 3; ++i) r2 += (r[i] - along * axis_dir_[i]) * (r[i] - along * axis_dir_[i]);
        totals.radius_max = std::max(totals.radius_max, std::sqrt(r2));
      }
      if (p.model != InterfaceModel::frictionless)
        apply_interface(p, k, best.face, best.proj.shape, best.proj.normal, best.proj.gap, v, force, acc);
    }
    if (has_axis_ && p.primary) totals.radius_edge = edge_radius(p, x);
  }
  totals.normal_force = totals.compressive_force - totals.adhesive_force;
  totals.tangential_force =
      std::sqrt(acc.friction[0] * acc.friction[0] + acc.friction[1] * acc.friction[1] + acc.friction[2] * acc.friction[2]);
  return totals;
}

// Mean distance from the axis of the points where the gap changes sign along slave-face edges
// (linear interpolation of g between an edge's two nodes): the contact boundary located between
// nodes, so the radius does not jump by a node spacing when a ring of nodes enters contact.
double ContactManager::edge_radius(const Pass& p, const double* x) const {
  const ContactSurface& slave = surfaces_[p.slave];
  double sum = 0.0;
  int count = 0;
  for (int f = 0; f < slave.face_count(); ++f)
    for (int e = 0; e < 4; ++e) {
      const int a = slave.face_nodes[4 * f + e], b = slave.face_nodes[4 * f + (e + 1) % 4];
      const double ga = p.gap[slave.face_local[4 * f + e]], gb = p.gap[slave.face_local[4 * f + (e + 1) % 4]];
      if (!(ga < 0.0 && gb >= 0.0)) continue;  // each crossing edge once: from inside to outside
      const double t = ga / (ga - gb);
      double r[3], along = 0.0;
      for (int i = 0; i < 3; ++i) {
        r[i] = x[3 * a + i] + t * (x[3 * b + i] - x[3 * a + i]) - axis_point_[i];
        along += r[i] * axis_dir_[i];
      }
      double r2 = 0.0;
      for (int i = 0; i < 3; ++i) r2 += (r[i] - along * axis_dir_[i]) * (r[i] - along * axis_dir_[i]);
      sum += std::sqrt(r2);
      ++count;
    }
  return count ? sum / count : 0.0;
}

std::vector<ContactManager::Overlap> ContactManager::initial_overlaps(const double* x, int worst_count) {
  std::vector<Overlap> out;
  for (auto& p : passes_) {
    search(p, x);
    const ContactSurface& slave = surfaces_[p.slave];
    const ContactSurface& master = surfaces_[p.master];
    std::vector<Overlap> pass;
    for (int k = 0; k < slave.node_count(); ++k) {
      const int count = p.candidate_offset[k + 1] - p.candidate_offset[k];
      if (count == 0) continue;
      const BestFace best = closest_face(x, master, &p.candidates[p.candidate_offset[k]], count, x + 3 * slave.nodes[k]);
      if (best.face >= 0 && best.proj.interior)
        pass.push_back({slave.name + " -> " + master.name, slave.nodes[k], best.proj.gap});
    }
    std::sort(pass.begin(), pass.end(), [](const Overlap& a, const Overlap& b) { return a.gap < b.gap; });
    if (pass.size() > static_cast<std::size_t>(worst_count)) pass.resize(static_cast<std::size_t>(worst_count));
    out.insert(out.end(), pass.begin(), pass.end());
  }
  return out;
}

}  // namespace tribex::contact
