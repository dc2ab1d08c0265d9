// SPDX-License-Identifier: MIT
#include "contact/mortar/mortar_enforcement.hpp"

#include <algorithm>
#include <cmath>

namespace tribex::contact {

double mortar_penalty_per_area(const ContactSurface& slave, const ContactSurface& master,
                               const std::vector<double>& mass, double scale, double dt) {
  auto smallest = [&](const ContactSurface& s) {
    double r = INFINITY;
    for (int k = 0; k < s.node_count(); ++k) r = std::min(r, mass[s.nodes[k]] / s.node_area[k]);
    return r;
  };
  const double a = smallest(slave), b = smallest(master);
  return scale * (a * b / (a + b)) / (dt * dt);
}

double max_face_diameter(const ContactSurface& surface, const double* x, const char* present) {
  double d2 = 0.0;
  for (int f = 0; f < surface.face_count(); ++f) {
    const int* fn = &surface.face_nodes[4 * f];
    if (present && !(present[fn[0]] && present[fn[1]] && present[fn[2]] && present[fn[3]])) continue;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double* p = x + 3 * surface.face_nodes[4 * f + a];
        const double* q = x + 3 * surface.face_nodes[4 * f + b];
        d2 = std::max(d2, (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
      }
  }
  return std::sqrt(d2);
}

MortarEnforcement::MortarEnforcement(const ContactSurface& slave) {
  const auto n = static_cast<std::size_t>(slave.node_count());
  weighted_gap_.assign(n, 0.0);
  overlap_area_.assign(n, 0.0);
  mean_gap_.assign(n, NAN);
  pressure_.assign(n, 0.0);
}

void MortarEnforcement::reserve(const ContactSurface& slave, const std::vector<int>& candidate_offset) {
  std::size_t pairs = 0;
  for (int f = 0; f < slave.face_count(); ++f) {
    const int k = slave.face_local[4 * f];
    pairs += static_cast<std::size_t>(candidate_offset[k + 1] - candidate_offset[k]);
  }
  // Headroom: later searches of a sliding or deforming contact find a few more pairs, and the
  // step loop must not allocate.
  if (segments_.capacity() < pairs + pairs / 4) segments_.reserve(pairs + pairs / 2 + 16);
}

MortarTotals MortarEnforcement::apply(const double* x, const ContactSurface& slave, const ContactSurface& master,
                                      const std::vector<int>& candidate_offset, const std::vector<int>& candidates,
                                      const MortarSettings& settings, double* force, double* traction) {
  MortarTotals totals;
  std::fill(weighted_gap_.begin(), weighted_gap_.end(), 0.0);
  std::fill(overlap_area_.begin(), overlap_area_.end(), 0.0);
  segments_.clear();
  // Sweep 1: segments, weighted gaps, and the adhesion traction at the integration points.
  for (int f = 0; f < slave.face_count(); ++f) {
    const int* sn = &slave.face_nodes[4 * f];
    const int* sl = &slave.face_local[4 * f];
    const int k0 = sl[0];
    if (candidate_offset[k0 + 1] == candidate_offset[k0]) continue;
    MortarTotals uncounted;
    MortarTotals& face_totals = !settings.counted || settings.counted[sn[0]] ? totals : uncounted;
    double X[12];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = x[3 * sn[a] + i];
    const SlaveFacePlane plane = slave_face_plane(X);
    for (int c = candidate_offset[k0]; c < candidate_offset[k0 + 1]; ++c) {
      const int mface = candidates[c];
      const int* mn = &master.face_nodes[4 * mface];
      bool shared = false;  // self-contact of one surface: a face never contacts its neighbours
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) shared |= mn[a] == sn[b];
      if (shared) continue;
      double Y[12];
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i) Y[3 * a + i] = x[3 * mn[a] + i];
      Segment s{};
      SegmentSums sums{};
      if (!integrate_pair(plane, Y, settings, face_totals, s, sums)) continue;
      s.slave_face = f;
      s.master_face = mface;
      for (int a = 0; a < 4; ++a) {
        weighted_gap_[sl[a]] += sums.gap[a];
        overlap_area_[sl[a]] += sums.area[a];
      }
      if (settings.adhesion)
        for (int a = 0; a < 4; ++a)
          for (int i = 0; i < 3; ++i) {
            force[3 * sn[a] + i] += sums.adhesion_slave[3 * a + i];
            traction[3 * sn[a] + i] += sums.adhesion_slave[3 * a + i] / slave.node_area[sl[a]];
            force[3 * mn[a] + i] -= sums.adhesion_master[3 * a + i];
          }
      segments_.push_back(s);
    }
  }
  nodal_pressures(slave, settings, totals);
  apply_pressures(slave, master, force, traction);
  return totals;
}

// The segment of a slave face's plane and a master face (docs/theory.md 5.3): its quadrature, the
// mortar matrices M, D (and the slope terms G, H), the weighted gap and area per slave node, and the
// Lennard-Jones traction at each integration point (6.1) as nodal forces.
bool MortarEnforcement::integrate_pair(const SlaveFacePlane& plane, const double Y[12], const MortarSettings& settings,
                                       MortarTotals& face_totals, Segment& s, SegmentSums& sums) {
  SegmentQuadrature& q = quadrature_;
  if (!integrate_segment(plane, Y, q, settings.adhesion)) return false;
  double g_min = INFINITY, g_max = -INFINITY;
  for (int p = 0; p < q.count; ++p) {
    g_min = std::min(g_min, q.gap[p]);
    g_max = std::max(g_max, q.gap[p]);
  }
  // Beyond the capture distance, or deeper than the margin (the far side of a thin body).
  if (g_min > settings.margin || g_max < -settings.margin) return false;
  for (int i = 0; i < 3; ++i) {
    s.normal[i] = plane.normal[i];
    s.e1[i] = plane.e1[i];
    s.e2[i] = plane.e2[i];
  }
  const double factor = settings.factor;
  double gap_sum[4] = {0, 0, 0, 0}, area_sum[4] = {0, 0, 0, 0};  // local: no aliasing with s in the loop
  for (int p = 0; p < q.count; ++p) {
    const double w = q.weight[p], g = q.gap[p];
    const double* N = q.slave_shape[p];
    const double* Phi = q.master_shape[p];
    const double s0 = q.master_slope[p][0], s1 = q.master_slope[p][1];
    double wN[4];
    for (int a = 0; a < 4; ++a) {
      wN[a] = w * N[a];
      gap_sum[a] += wN[a] * g;
      area_sum[a] += wN[a];
    }
    for (int a = 0; a < 4; ++a) {
      const double wPhi = w * Phi[a];
      for (int b = a; b < 4; ++b) {  // M and G are symmetric in (a, b)
        const double m = wN[a] * N[b];
        s.M[a][b] += m;
        s.G[a][b][0] += m * s0;
        s.G[a][b][1] += m * s1;
      }
      for (int b = 0; b < 4; ++b) {
        const double d = wPhi * N[b];
        s.D[a][b] += d;
        s.H[a][b][0] += d * s0;
        s.H[a][b][1] += d * s1;
      }
    }
    if (!settings.adhesion) continue;
    // The law's separation is the distance to the master's tangent plane, g (-n_s . n_m) (g is
    // measured along n_s), as the node-to-face rule measures it along n_m.
    const double* nm = q.master_normal[p];
    const double separation = -g * (plane.normal[0] * nm[0] + plane.normal[1] * nm[1] + plane.normal[2] * nm[2]);
    if (!(separation <= settings.law.capture_gap())) continue;
    face_totals.adhesion_energy += factor * w * adhesive_energy(separation, settings.law);
    const double sigma = adhesive_traction(separation, settings.law);  // 0 for g < 0 (penalty side)
    if (sigma == 0.0) continue;
    face_totals.adhesive_force += factor * sigma * w;
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) {
        // The slave point pulled toward the master (against n_m), the master point back.
        sums.adhesion_slave[3 * a + i] -= factor * sigma * w * N[a] * nm[i];
        sums.adhesion_master[3 * a + i] -= factor * sigma * w * Phi[a] * nm[i];
      }
  }
  for (int a = 0; a < 4; ++a) {
    sums.gap[a] = gap_sum[a];
    sums.area[a] = area_sum[a];
  }
  return true;
}

// Nodal pressures p_j = k_A (-g~_j / A_j) where the mean gap is a penetration within the margin.
void MortarEnforcement::nodal_pressures(const ContactSurface& slave, const MortarSettings& settings, MortarTotals& totals) {
  for (int k = 0; k < slave.node_count(); ++k) {
    pressure_[k] = 0.0;
    mean_gap_[k] = overlap_area_[k] > 0.0 ? weighted_gap_[k] / overlap_area_[k] : NAN;
    if (overlap_area_[k] > 0.0 && mean_gap_[k] < 0.0 && -mean_gap_[k] <= settings.margin) {
      pressure_[k] = settings.factor * settings.penalty_per_area * (-mean_gap_[k]);
      if (!settings.counted || settings.counted[slave.nodes[k]]) totals.compressive_force += pressure_[k] * overlap_area_[k];
    }
  }
}

// Sweep 2: f_i = -n_s sum_j M_ij p_j + sum_j G_ij p_j on the slave, f_k = +n_s sum_j D_kj p_j - sum_j H_kj p_j
// on the master.
void MortarEnforcement::apply_pressures(const ContactSurface& slave, const ContactSurface& master, double* force,
                                        double* traction) const {
  for (const Segment& s : segments_) {
    const int* sn = &slave.face_nodes[4 * s.slave_face];
    const int* sl = &slave.face_local[4 * s.slave_face];
    const int* mn = &master.face_nodes[4 * s.master_face];
    const double p[4] = {pressure_[sl[0]], pressure_[sl[1]], pressure_[sl[2]], pressure_[sl[3]]};
    if (p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0 && p[3] == 0.0) continue;
    for (int a = 0; a < 4; ++a) {
      double fs = 0.0, fm = 0.0, ts[2] = {0, 0}, tm[2] = {0, 0};
      for (int b = 0; b < 4; ++b) {
        const int lo = std::min(a, b), hi = std::max(a, b);  // symmetric M, G: upper triangle
        fs += s.M[lo][hi] * p[b];
        ts[0] += s.G[lo][hi][0] * p[b];
        ts[1] += s.G[lo][hi][1] * p[b];
        fm += s.D[a][b] * p[b];
        tm[0] += s.H[a][b][0] * p[b];
        tm[1] += s.H[a][b][1] * p[b];
      }
      for (int i = 0; i < 3; ++i) {
        const double f_slave = -fs * s.normal[i] + ts[0] * s.e1[i] + ts[1] * s.e2[i];
        force[3 * sn[a] + i] += f_slave;
        traction[3 * sn[a] + i] += f_slave / slave.node_area[sl[a]];
        force[3 * mn[a] + i] += fm * s.normal[i] - tm[0] * s.e1[i] - tm[1] * s.e2[i];
      }
    }
  }
}

}  // namespace tribex::contact
