// SPDX-License-Identifier: MIT
// Segment-to-segment (mortar) penalty contact and face-quadrature adhesion for one interaction
// pass (slave surface -> master surface), used by ContactManager when `enforcement = mortar`.
//
// For every slave face and each candidate master face the overlap is integrated
// (segment_quadrature). Per slave node j (slave shape functions N_j, master Phi_k):
//   weighted gap        g~_j = sum_seg int N_j g dA,      overlap area A_j = sum_seg int N_j dA,
//   nodal pressure      p_j  = k_A max(0, -g~_j / A_j)    (k_A penalty per area, Pa/m),
//   slave forces        f_i  = -n_s sum_j M_ij p_j + sum_j G_ij p_j,  M_ij = int N_i N_j dA,
//   master forces       f_k  = +n_s sum_j D_kj p_j - sum_j H_kj p_j,  D_kj = int Phi_k N_j dA,
// with the tangential terms G_ij = int N_i N_j grad h_m dA, H_kj = int Phi_k N_j grad h_m dA from
// the master's slope (zero on a flat master), i.e. f = -dPi/dx of
// Pi = (k_A/2) sum_j A_j (g~_j/A_j)^2 at fixed slave normal and integration points. A uniform pressure p
// gives f_i = p int N_i dA on both sides (the consistent nodal loads, so the contact patch test
// passes with non-matching meshes), and sum_i M_ij = int N_j dA = sum_k D_kj conserves momentum
// exactly. Adhesion (docs/theory.md 6.2) is evaluated at the integration points from the separation
// there, s = g (-n_s . n_m) (the distance to the master's tangent plane, n_m its outward normal at
// the point): f_i -= sigma_s(s) w N_i n_m on the slave, f_k += sigma_s(s) w Phi_k n_m on the master,
// i.e. the node-to-face rule (sigma_s(g_I) A_I along n_m) with the nodal sampling replaced by the
// face quadrature.
//
// Storage (nodal arrays, the segment list) is sized at construction and at each search, so a step
// between searches allocates nothing.
#pragma once

#include <vector>

#include "contact/models/adhesion_lj.hpp"
#include "contact/mortar/segment_quadrature.hpp"
#include "contact/surface.hpp"

namespace tribex::contact {

struct MortarSettings {
  double factor = 1.0;             // pass partition factor (1/2 for each pass of a symmetric interaction)
  double margin = 0.0;             // a pair deeper than this is the far side of a thin body, not a contact, m
  double penalty_per_area = 0.0;   // k_A, Pa/m
  bool adhesion = false;           // add the Lennard-Jones traction at the integration points
  AdhesionLaw law;
  // Distributed runs: [node] nonzero for the nodes whose totals this rank reports (a slave face's
  // adhesion by its first node); nullptr: all (ContactManager::distribute).
  const char* counted = nullptr;
};

/// Totals of one pass (forces on the slave side, N; energy J).
struct MortarTotals {
  double compressive_force = 0.0;  // sum_j p_j A_j
  double adhesive_force = 0.0;     // sum over points of sigma_s w (attractive, positive)
  double adhesion_energy = 0.0;    // sum over points of U(g) w (<= 0)
};

/// k_A = s m_A / dt^2 with m_A = a b / (a + b), a and b the smallest mass per overlap area
/// m_I / A_I on the slave and master surfaces (the per-area analogue of k_p = s m_eff / dt^2,
/// docs/theory.md 5.2): one value for the whole surface pair, so that a uniform gap gives a uniform
/// pressure; the smallest ratio keeps every node inside the central-difference limit.
double mortar_penalty_per_area(const ContactSurface& slave, const ContactSurface& master,
                               const std::vector<double>& mass, double scale, double dt);

/// Largest distance between two nodes of one face (m): the search capture of a mortar pass is
/// the margin plus this, so that every master face overlapping a slave face is a candidate of
/// each of that face's nodes. `present` [node] (nullptr: every node): only the faces whose four nodes
/// this rank holds (contact_manager.hpp, distribute).
double max_face_diameter(const ContactSurface& surface, const double* x, const char* present = nullptr);

class MortarEnforcement {
 public:
  explicit MortarEnforcement(const ContactSurface& slave);

  /// After a search: room for one segment per (slave face, candidate master face) pair.
  void reserve(const ContactSurface& slave, const std::vector<int>& candidate_offset);

  /// Adds the pass's forces to `force` [node][3] and `traction` [node][3] (slave nodes: force /
  /// tributary area). Candidates: CSR per slave node (those of each face's first node are used).
  MortarTotals apply(const double* x, const ContactSurface& slave, const ContactSurface& master,
                     const std::vector<int>& candidate_offset, const std::vector<int>& candidates,
                     const MortarSettings& settings, double* force, double* traction);

  /// Per slave node after apply(): mean gap g~_j / A_j (NaN without overlap), m; overlap area A_j,
  /// m^2; penalty pressure p_j (factor included), Pa.
  const std::vector<double>& mean_gap() const { return mean_gap_; }
  const std::vector<double>& overlap_area() const { return overlap_area_; }
  const std::vector<double>& pressure() const { return pressure_; }

 private:
  struct Segment {
    int slave_face, master_face;
    double normal[3];
    double M[4][4];  // int N_a N_b dA (upper triangle b >= a filled)
    double D[4][4];  // int Phi_k N_b dA
    double G[4][4][2];  // int N_a N_b grad h_m dA, components along e1, e2 (upper triangle b >= a filled)
    double H[4][4][2];  // int Phi_k N_b grad h_m dA, along e1, e2
    double e1[3], e2[3];
  };
  // A segment's sums over its integration points besides the matrices: weighted gap and area per
  // slave node, and the adhesive nodal forces on the slave and master face (N, [node][3]).
  struct SegmentSums {
    double gap[4], area[4];
    double adhesion_slave[12], adhesion_master[12];
  };
  // apply()'s steps: one slave face against one master face (false: no overlap within the margin),
  // the nodal pressures from the weighted gaps, and the pressures' nodal forces.
  bool integrate_pair(const SlaveFacePlane& plane, const double Y[12], const MortarSettings& settings,
                      MortarTotals& face_totals, Segment& s, SegmentSums& sums);
  void nodal_pressures(const ContactSurface& slave, const MortarSettings& settings, MortarTotals& totals);
  void apply_pressures(const ContactSurface& slave, const ContactSurface& master, double* force, double* traction) const;
  std::vector<double> weighted_gap_, overlap_area_, mean_gap_, pressure_;
  std::vector<Segment> segments_;
  SegmentQuadrature quadrature_;
};

}  // namespace tribex::contact
