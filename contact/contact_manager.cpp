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

// Totals of the interface models over the passes of one step.
struct ContactManager::Accumulator {
  ContactTotals& totals;
  const double* x;
  double friction[3] = {0.0, 0.0, 0.0};  // vector sum of shear forces on the (first) slave surfaces, N
};

// 4. interface models on slave surface node k projecting inside master face `face` with gap g:
// adhesion sigma_s(g + z0) A_I toward the master for g >= 0 (docs/theory.md 6.2), and for the junction
// model the pair is recorded for the shear of step 5 when in contact (g <= g_j; docs/theory.md 7.1-7.2).
// Penalty contact (g < 0) has been applied and counted by the caller; here a node with
// 0 <= g <= g_j is counted as in contact (area, status, radius) as well.
void ContactManager::apply_interface(Pass& p, int k, int face, const double* shape, const double* normal, double gap,
                                     double* force, Accumulator& acc) {
  const ContactSurface& slave = surfaces_[p.slave];
  const ContactSurface& master = surfaces_[p.master];
  const int node = slave.nodes[k];
  const int* fn = &master.face_nodes[4 * face];
  const double area = slave.node_area[k];
  ContactTotals& totals = acc.totals;
  totals.adhesion_energy += p.factor * area * adhesive_energy(gap, p.adhesion);
  const bool in_contact = gap <= p.junction.gap_tolerance;
  if (in_contact && gap >= 0.0) {  // g < 0 was counted by the penalty branch
    status_[node] = 1.0;
    if (p.model != InterfaceModel::junction) totals.area += p.factor * area;  // junction: from the shares (step 5)
    if (p.primary) ++totals.nodes;
    if (has_axis_) totals.radius_max = std::max(totals.radius_max, axis_distance(acc.x + 3 * node, axis_point_, axis_dir_));
  }
  // Junction: every node near the master is a candidate pair; its share of the contact area
  // (step 5) decides whether it carries shear (a node just outside g_j can own part of a face
  // that is in contact).
  if (p.model == InterfaceModel::junction) {
    const int j = p.junction_count++;
    p.junction_slave[j] = k;
    p.junction_face[j] = face;
    for (int a = 0; a < 4; ++a) p.junction_shape[4 * j + a] = shape[a];
    for (int i = 0; i < 3; ++i) p.junction_normal[3 * j + i] = normal[i];
  }
  if (gap < 0.0) return;
  // Attraction: toward the master face, i.e. against its outward normal.
  const double fa = p.factor * adhesive_traction(gap, p.adhesion) * area;
  totals.adhesive_force += fa;
  for (int i = 0; i < 3; ++i) {
    const double f = -fa * normal[i];
    force[3 * node + i] += f;
    for (int a = 0; a < 4; ++a) force[3 * fn[a] + i] -= shape[a] * f;
    traction_[3 * node + i] += f / area;
  }
}

// Junction shear tau A_I on a slave node in contact (docs/theory.md 7.1-7.2), added to f (force on the
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
  // (its slope at zero slip, docs/theory.md 7.3) needs dt < 2 m_eff / c_I.
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

// In-contact part of each slave node's tributary area, int over {g <= g_j} of N_I dA: the nodal
// gaps interpolated bilinearly over each slave face (nodes without a projection count as far) and
// the contact indicator sampled at 8 x 8 midpoints; faces with all four nodes in contact give
// A_f / 4 per node (exact for parallelograms) without sampling. Reference face areas, like A_I.
void ContactManager::contact_shares(Pass& p) {
  const ContactSurface& slave = surfaces_[p.slave];
  std::fill(p.contact_share.begin(), p.contact_share.end(), 0.0);
  const double gj = p.junction.gap_tolerance;
  constexpr int n = 8;
  for (int f = 0; f < slave.face_count(); ++f) {
    const int* loc = &slave.face_local[4 * f];
    double g[4];
    int inside = 0;
    for (int a = 0; a < 4; ++a) {
      const double ga = p.gap[loc[a]];
      g[a] = std::isnan(ga) ? INFINITY : ga;
      inside += g[a] <= gj;
    }
    const double Af = slave.face_area[f];
    if (inside == 0) continue;
    if (inside == 4) {
      for (int a = 0; a < 4; ++a) p.contact_share[loc[a]] += 0.25 * Af;
      continue;
    }
    const double far = p.margin;  // a finite stand-in for "no projection" in the interpolation
    for (double& ga : g) ga = std::min(ga, far);
    const double dA = Af / (n * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double xi = -1.0 + (2.0 * i + 1.0) / n, eta = -1.0 + (2.0 * j + 1.0) / n;
        const double N[4] = {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
                             0.25 * (1 - xi) * (1 + eta)};
        const double gs = N[0] * g[0] + N[1] * g[1] + N[2] * g[2] + N[3] * g[3];
        if (gs > gj) continue;
        for (int a = 0; a < 4; ++a) p.contact_share[loc[a]] += N[a] * dA;
      }
  }
}

// 5. junction shear on the pairs recorded in step 4 (docs/theory.md 7.1, 7.3; models/junction_shear.hpp).
// Per pair, with the relative velocity v_r = v_slave - sum_a N_a v_a and its tangential part v_t:
//  - predicted v_t at n+3/2 without the shear: v^{n+1/2} + dt (other + contact normal forces) / m,
//    node by node, then the same relative tangential projection;
//  - the pair mass: a shear F on the slave and -N_a F on the master nodes changes v_r by
//    dt F (1/m_s + sum_a N_a^2 / m_a) when the pair is alone; with every pair loaded at once a master
//    node a takes sum_b N_a(b) F_b, so the row sum 1/m_pair = 1/m_s + sum_a N_a S_a / m_a with
//    S_a = sum over pairs of N_a bounds the coupled change (Gershgorin): the simultaneous
//    backward-Euler updates under-relax rather than overshoot. For one pair S_a = N_a.
//  - F from junction_update, capped at factor tau* A_I and at the stick force m_pair |v_pred| / dt.
// Nodes with prescribed velocities are treated as free here (their velocity is overwritten after
// the update): the pair mass is then too small and the update under-relaxes, which stays stable.
void ContactManager::apply_junction(Pass& p, const double* v, const double* other_force, double dt, double* force,
                                    Accumulator& acc) {
  const ContactSurface& slave = surfaces_[p.slave];
  const ContactSurface& master = surfaces_[p.master];
  ContactTotals& totals = acc.totals;
  contact_shares(p);
  // Keep the pairs that own contact area.
  int count = 0;
  for (int j = 0; j < p.junction_count; ++j) {
    const double share = p.contact_share[p.junction_slave[j]];
    totals.area += p.factor * share;
    if (!(share > 0.0)) continue;
    p.junction_slave[count] = p.junction_slave[j];
    p.junction_face[count] = p.junction_face[j];
    for (int a = 0; a < 4; ++a) p.junction_shape[4 * count + a] = p.junction_shape[4 * j + a];
    for (int i = 0; i < 3; ++i) p.junction_normal[3 * count + i] = p.junction_normal[3 * j + i];
    ++count;
  }
  auto predicted = [&](int node, int i) {
    const double f = force[3 * node + i] + (other_force ? other_force[3 * node + i] : 0.0);
    return v[3 * node + i] + dt * f / mass_[node];
  };
  for (int j = 0; j < count; ++j) {
    const int* fn = &master.face_nodes[4 * p.junction_face[j]];
    for (int a = 0; a < 4; ++a) master_share_[fn[a]] += p.junction_shape[4 * j + a];
  }
  // Trial velocities of all pairs first (Jacobi: the forces of one pair do not enter another's trial).
  for (int j = 0; j < count; ++j) {
    const int node = slave.nodes[p.junction_slave[j]];
    const int* fn = &master.face_nodes[4 * p.junction_face[j]];
    const double* N = &p.junction_shape[4 * j];
    const double* n = &p.junction_normal[3 * j];
    double vr[3], vp[3];
    for (int i = 0; i < 3; ++i) {
      vr[i] = v[3 * node + i];
      vp[i] = predicted(node, i);
      for (int a = 0; a < 4; ++a) {
        vr[i] -= N[a] * v[3 * fn[a] + i];
        vp[i] -= N[a] * predicted(fn[a], i);
      }
    }
    const double vrn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
    const double vpn = vp[0] * n[0] + vp[1] * n[1] + vp[2] * n[2];
    for (int i = 0; i < 3; ++i) {
      p.junction_vt[3 * j + i] = vr[i] - vrn * n[i];
      p.junction_vpred[3 * j + i] = vp[i] - vpn * n[i];
    }
  }
  const double sign = p.primary ? 1.0 : -1.0;
  for (int j = 0; j < count; ++j) {
    const int k = p.junction_slave[j];
    const int node = slave.nodes[k];
    const int* fn = &master.face_nodes[4 * p.junction_face[j]];
    const double* N = &p.junction_shape[4 * j];
    double inv_m = 1.0 / mass_[node];
    for (int a = 0; a < 4; ++a) inv_m += N[a] * master_share_[fn[a]] / mass_[fn[a]];
    // A symmetric interaction updates the pair in both passes, each with half the capacity and
    // half the stick force (pair mass times the pass factor).
    const double m_pair = p.factor / inv_m;
    const double area = p.contact_share[k];
    const JunctionUpdate up = junction_update(&p.junction_vt[3 * j], &p.junction_vpred[3 * j],
                                              p.factor * p.junction.strength * area, m_pair, dt, p.junction);
    for (int i = 0; i < 3; ++i) {
      force[3 * node + i] += up.force[i];
      for (int a = 0; a < 4; ++a) force[3 * fn[a] + i] -= N[a] * up.force[i];
      traction_[3 * node + i] += up.force[i] / slave.node_area[k];
      acc.friction[i] += sign * up.force[i];
    }
    totals.friction_power += up.power;
    totals.junction_capacity += p.factor * p.junction.strength * area;
  }
  for (int j = 0; j < count; ++j) {
    const int* fn = &master.face_nodes[4 * p.junction_face[j]];
    for (int a = 0; a < 4; ++a) master_share_[fn[a]] = 0.0;
  }
  p.junction_count = 0;
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
      double crossing[3];
      for (int i = 0; i < 3; ++i) crossing[i] = x[3 * a + i] + t * (x[3 * b + i] - x[3 * a + i]);
      sum += axis_distance(crossing, axis_point_, axis_dir_);
      ++count;
    }
  return count ? sum / count : 0.0;
}

// Contact radius from the nodal penalty pressures p_I = f_I / A_I of the contacting slave nodes: the
// least-squares line p^2 = alpha - beta r^2 through the points (r_I^2, p_I^2), and a^2 = alpha / beta,
// the zero of the fitted p^2. Exact for the elliptic pressure p = p0 sqrt(1 - r^2/a^2) of Hertz (and
// the compressive part of DMT) contact, whatever the node positions relative to the edge; every
// contacting node contributes, so the radius does not step as a ring of nodes enters contact. It
// presumes that shape: for another pressure profile it is a shape-fitted, not a measured, radius.
// The nodal forces (not the penetrations, whose penalty stiffness varies with the projection point)
// carry the pressure. 0 with fewer than 3 nodes, all nodes at one radius, or a p^2 that does not fall with r.
double ContactManager::pressure_fit_radius() const {
  const std::size_t n = fit_r2_.size();
  if (n < 3) return 0.0;
  double mean_r2 = 0.0, mean_p2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mean_r2 += fit_r2_[i];
    mean_p2 += fit_p2_[i];
  }
  mean_r2 /= double(n);
  mean_p2 /= double(n);
  double srr = 0.0, srp = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    srr += (fit_r2_[i] - mean_r2) * (fit_r2_[i] - mean_r2);
    srp += (fit_r2_[i] - mean_r2) * (fit_p2_[i] - mean_p2);
  }
  // All nodes at one radius (to round-off): nothing to fit.
  if (!(srr > 1e-12 * double(n) * mean_r2 * mean_r2) || !(srp < 0.0)) return 0.0;
  const double slope = srp / srr;  // -p0^2 / a^2
  const double a2 = mean_r2 - mean_p2 / slope;
  return a2 > 0.0 ? std::sqrt(a2) : 0.0;
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
