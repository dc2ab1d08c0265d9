// SPDX-License-Identifier: MIT
// What a contact step reports: the totals over every interaction pass (forces, areas, energies, the
// run guards' penetration and motion figures, contact-radius estimates).
#pragma once

#include <cmath>

namespace tribex::contact {

// Forces are those acting on the slave surfaces (for a symmetric interaction the second pass's
// forces enter with the sign of the reaction on the first slave).
struct ContactTotals {
  double normal_force = 0.0;       // net normal force on slave nodes, compressive - adhesive, N
  double tangential_force = 0.0;   // magnitude of the vector sum of junction shear forces, N
  double compressive_force = 0.0;  // sum of penalty (repulsive) normal forces, N
  double adhesive_force = 0.0;     // sum of attractive adhesion forces (positive), N
  double adhesion_energy = 0.0;    // adhesive potential sum_I A_I U(g_I) (<= 0), J
  double junction_capacity = 0.0;  // tau* x contact area (junction model), N
  double friction_power = 0.0;     // sum_I -F_t,I . (v_t^{n+1/2} + v_t^+)/2 dissipated by the junction shear, W
  double area = 0.0;               // contact area: tributary areas of slave nodes in contact (junction: in-contact face parts), m^2
  int nodes = 0;                   // slave nodes in contact (first pass of each interaction)
  double max_penetration = 0.0;    // m
  // Run guards (solver/guards/README.md): the deepest penetration in local element sizes, max over
  // slave nodes of -g / sqrt(A_I) (A_I the node's tributary area), and the largest one-step motion of
  // the surfaces against the capture distance, max over passes of dt (max|v_slave| + max|v_master|) / margin:
  // a bound on the relative normal approach per step; past 1 a node can cross the master unseen.
  double max_penetration_ratio = 0.0;
  int penetration_node = -1;       // global node of max_penetration_ratio (-1: none)
  double motion_ratio = 0.0;
  int motion_node = -1;            // global node moving fastest in the pass of motion_ratio
  double radius_max = 0.0;         // farthest contacting node from the axis (if one is set), m
  double radius_edge = 0.0;        // mean axis distance of the gap sign changes on slave-face edges, m
  double radius_pressure_fit = 0.0;  // a of the elliptic pressure p^2 = p0^2 (1 - r^2/a^2) fitted to the nodal pressures, m
  int searches = 0;                // broad-phase builds this step
  // rough_surface model (slave side, partition factor applied):
  double real_area = 0.0;          // sum A_I (A_c/A_0)(d_I), m^2
  double asperity_contacts = 0.0;  // sum A_I (N/A_0)(d_I): asperities in contact
  double nominal_area = 0.0;       // sum A_I over nodes with d_I below the contact separation, m^2
  double apparent_pressure() const { return nominal_area > 0.0 ? normal_force / nominal_area : 0.0; }
};

/// Records a penetration `depth` (m) of a slave node (global index) with tributary area `area` (m^2)
/// in the guard fields of `t`.
inline void note_penetration(ContactTotals& t, double depth, double area, int node) {
  if (!(depth > 0.0) || !(area > 0.0)) return;
  const double ratio = depth / std::sqrt(area);
  if (ratio > t.max_penetration_ratio) {
    t.max_penetration_ratio = ratio;
    t.penetration_node = node;
  }
}

}  // namespace tribex::contact
