// SPDX-License-Identifier: MIT
// ContactManager's interface models on the node-to-face path (steps 4 and 5 of compute_forces,
// contact/contact_manager.hpp): Lennard-Jones adhesion, the junction shear with its contact shares,
// the rough-surface (GW) law. compute_forces (contact_manager.cpp) projects each slave node and
// calls these with the node, its master face and gap.
#include <algorithm>
#include <cmath>

#include "contact/contact_manager.hpp"
#include "contact/geometry/axis_distance.hpp"

namespace tribex::contact {

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

}  // namespace tribex::contact
