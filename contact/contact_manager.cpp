// SPDX-License-Identifier: MIT
#include "contact/contact_manager.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/geometry/axis_distance.hpp"
#include "contact/geometry/quad_projection.hpp"

namespace tribex::contact {
namespace {

struct BestFace {
  int face = -1;
  Projection proj;
  bool usable = false;  // proj.interior, or the closest point is a kink of the master (see at_kink)
};

// A node that no candidate face projects in its interior, whose closest point lies on an edge or a
// vertex inside the master surface (not on its boundary), sits in the wedge in front of a ridge or
// behind a valley of the faceted surface: a soft master folds into a valley under each of the slave's
// point loads, and the loaded node sits below it (tests/contact/kink_test.cpp). Its gap is then the signed distance to that point, along the line to it
// (the face normal otherwise), so the gap and the force direction stay continuous as the node
// crosses from a face's region into the wedge. Dropping such a node, as the projection alone would,
// removes a penalty force with its stored energy 1/2 k g^2 and adds it back on re-entry: on a 2 nm
// coating that made the contact inject up to 10 % of the energy (issue 22, contact/README.md).
bool at_kink(const ContactSurface& master, int face, const double* p, Projection& proj) {
  const bool on_edge[4] = {proj.eta <= -1.0, proj.xi >= 1.0, proj.eta >= 1.0, proj.xi <= -1.0};
  for (int e = 0; e < 4; ++e)
    if (on_edge[e] && !master.edge_shared[4 * face + e]) return false;  // the surface's own boundary
  if (!(proj.distance > 0.0)) return false;
  const double sign = proj.gap < 0.0 ? -1.0 : 1.0;
  for (int i = 0; i < 3; ++i) proj.normal[i] = sign * (p[i] - proj.point[i]) / proj.distance;
  proj.gap = sign * proj.distance;
  return true;
}

// 2. narrow phase: among the candidates, prefer faces over which the node projects (interior),
// then the smallest |gap|; fall back to the nearest edge/vertex point.
// `hint` (the node's face of the previous step, or -1) is tried first and kept when the node still
// projects over it: between broad-phase searches a node usually stays over the same face, and this
// skips the projections onto the other candidates (docs/theory.md 5.1: track the current face).
BestFace closest_face(const double* x, const ContactSurface& master, const int* faces, int count, const double* p,
                      int hint = -1) {
  if (hint >= 0) {
    double X[12];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = x[3 * master.face_nodes[4 * hint + a] + i];
    const Projection pr = project_onto_quad(X, p);
    if (pr.interior) return {hint, pr, true};
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
      best = {f, pr, pr.interior};
      best_key = key;
      best_interior = pr.interior;
    }
  }
  if (best.face >= 0 && !best.usable) best.usable = at_kink(master, best.face, p, best.proj);
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
      if (p.model == InterfaceModel::junction) {
        const std::size_t n = surfaces_[p.slave].nodes.size();
        p.junction_slave.resize(n);
        p.junction_face.resize(n);
        p.junction_shape.resize(4 * n);
        p.junction_normal.resize(3 * n);
        p.junction_vt.resize(3 * n);
        p.junction_vpred.resize(3 * n);
        p.contact_share.resize(n);
      }
      if (it.enforcement == Enforcement::mortar) {
        if (it.model == InterfaceModel::junction || it.model == InterfaceModel::rough_surface)
          throw std::invalid_argument("contact interaction '" + it.name + "': the mortar enforcement supports models frictionless and adhesion");
        p.mortar = std::make_unique<MortarEnforcement>(surfaces_[p.slave]);
        p.penalty_per_area = mortar_penalty_per_area(surfaces_[p.slave], surfaces_[p.master], mass, p.penalty_scale, dt_ref);
      }
      passes_.push_back(std::move(p));
    }
  }
  traction_.assign(3 * static_cast<std::size_t>(node_count), 0.0);
  master_share_.assign(static_cast<std::size_t>(node_count), 0.0);
  status_.assign(static_cast<std::size_t>(node_count), 0.0);
  std::size_t primary_slave_nodes = 0;
  for (const auto& p : passes_)
    if (p.primary) primary_slave_nodes += surfaces_[p.slave].nodes.size();
  fit_r2_.reserve(primary_slave_nodes);
  fit_p2_.reserve(primary_slave_nodes);
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

// One-step motion of the pass's surfaces against its capture distance (ContactTotals::motion_ratio). It
// bounds the relative approach from the nodes' speeds alone, so it also sees a body that is still far
// from the other one and would pass through it within the step (tunnelling).
void ContactManager::track_motion(const Pass& p, const double* v, double dt, ContactTotals& totals) const {
  double fastest[2] = {0.0, 0.0};
  int node_of[2] = {-1, -1};
  for (int side = 0; side < 2; ++side)
    for (int node : surfaces_[side == 0 ? p.slave : p.master].nodes) {
      const double* vn = v + 3 * node;
      const double s2 = vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2];
      if (s2 > fastest[side]) {
        fastest[side] = s2;
        node_of[side] = node;
      }
    }
  const double capture = p.mortar && p.capture > 0.0 ? p.capture : p.margin;
  const double ratio = dt * (std::sqrt(fastest[0]) + std::sqrt(fastest[1])) / capture;
  if (ratio > totals.motion_ratio) {
    totals.motion_ratio = ratio;
    totals.motion_node = fastest[0] >= fastest[1] ? node_of[0] : node_of[1];
  }
}

void ContactManager::search(Pass& p, const double* x) {
  if (p.mortar && p.capture == 0.0) p.capture = p.margin + 1.25 * max_face_diameter(surfaces_[p.slave], x);
  bucket_.find_candidates(x, surfaces_[p.slave], surfaces_[p.master], p.mortar ? p.capture : p.margin,
                          p.candidate_offset, p.candidates);
  if (p.mortar) {
    // Headroom for later searches (the wide mortar capture gives more candidates): no allocation in the loop.
    if (p.candidates.capacity() < p.candidates.size() + p.candidates.size() / 4)
      p.candidates.reserve(p.candidates.size() + p.candidates.size() / 2);
    p.mortar->reserve(surfaces_[p.slave], p.candidate_offset);
  }
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

double ContactManager::stable_time_step() const {
  double dt = INFINITY;
  for (const auto& p : passes_) dt = std::min(dt, p.stable_dt);
  return dt;
}

ContactTotals ContactManager::compute_forces(const double* x, const double* v, double* force, const double* other_force,
                                             double dt) {
  if (!(dt > 0.0)) dt = dt_ref_;
  ContactTotals totals;
  Accumulator acc{totals, x};
  fit_r2_.clear();
  fit_p2_.clear();
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
    if (v) track_motion(p, v, dt, totals);
    if (p.mortar) {
      apply_mortar(p, x, force, totals);
      if (has_axis_ && p.primary) totals.radius_edge = edge_radius(p, x);
      continue;
    }
    for (int k = 0; k < slave.node_count(); ++k) {
      const int count = p.candidate_offset[k + 1] - p.candidate_offset[k];
      if (count == 0) continue;
      const int node = slave.nodes[k];
      const double* xs = x + 3 * node;
      const BestFace best = closest_face(x, master, &p.candidates[p.candidate_offset[k]], count, xs, p.last_face[k]);
      p.last_face[k] = best.face >= 0 && best.proj.interior ? best.face : -1;
      if (best.usable) p.gap[k] = best.proj.gap;
      if (p.model == InterfaceModel::rough_surface) {
        // The GW law is the whole normal contact (no penalty); a node deeper than the margin is the far side.
        if (best.usable && -best.proj.gap <= p.margin)
          apply_rough_surface(p, k, best.face, best.proj.shape, best.proj.normal, best.proj.gap, v, force, acc);
        continue;
      }
      if (p.model != InterfaceModel::frictionless && best.usable && best.proj.gap >= 0.0) {
        apply_interface(p, k, best.face, best.proj.shape, best.proj.normal, best.proj.gap, force, acc);
        continue;
      }
      if (!best.usable || best.proj.gap >= 0.0) continue;
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
      if (p.model != InterfaceModel::junction) totals.area += p.factor * area;  // junction: from the shares
      totals.max_penetration = std::max(totals.max_penetration, -best.proj.gap);
      note_penetration(totals, -best.proj.gap, area, node);
      if (p.primary) ++totals.nodes;
      if (has_axis_) {
        const double r2 = axis_distance_squared(xs, axis_point_, axis_dir_);
        totals.radius_max = std::max(totals.radius_max, std::sqrt(r2));
        if (p.primary) {
          const double pressure = fn_mag / (p.factor * area);
          fit_r2_.push_back(r2);
          fit_p2_.push_back(pressure * pressure);
        }
      }
      if (p.model != InterfaceModel::frictionless)
        apply_interface(p, k, best.face, best.proj.shape, best.proj.normal, best.proj.gap, force, acc);
    }
    if (p.model == InterfaceModel::junction && v) apply_junction(p, v, other_force, dt, force, acc);
    p.junction_count = 0;
    if (has_axis_ && p.primary) totals.radius_edge = edge_radius(p, x);
  }
  if (has_axis_) totals.radius_pressure_fit = pressure_fit_radius();
  totals.normal_force = totals.compressive_force - totals.adhesive_force;
  totals.tangential_force =
      std::sqrt(acc.friction[0] * acc.friction[0] + acc.friction[1] * acc.friction[1] + acc.friction[2] * acc.friction[2]);
  return totals;
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
      if (best.usable)
        pass.push_back({slave.name + " -> " + master.name, slave.nodes[k], best.proj.gap});
    }
    std::sort(pass.begin(), pass.end(), [](const Overlap& a, const Overlap& b) { return a.gap < b.gap; });
    if (pass.size() > static_cast<std::size_t>(worst_count)) pass.resize(static_cast<std::size_t>(worst_count));
    out.insert(out.end(), pass.begin(), pass.end());
  }
  return out;
}

}  // namespace tribex::contact
