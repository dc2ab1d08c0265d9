// SPDX-License-Identifier: MIT
// What a contact law sees of one node-to-face pass (contact/laws/README.md): the slave node projected
// on its master face (ContactPoint), and the pass's arrays and totals with the few operations a law
// performs on them (PassView). The pass itself (node_to_face_pass.cpp) finds the points, applies the
// penalty, and calls the law's hooks; the law never loops over nodes or touches the search.
#pragma once

#include <span>
#include <vector>

#include "contact/contact_reductions.hpp"
#include "contact/contact_totals.hpp"
#include "contact/surface.hpp"

namespace tribex::contact {

/// A slave node over its master face this step.
struct ContactPoint {
  int k = -1;                        // index of the node in the slave surface
  int node = -1;                     // global slave node
  int face = -1;                     // master face
  const int* face_nodes = nullptr;   // its 4 global nodes
  const double* shape = nullptr;     // [4] shape values N_a of the projection
  const double* normal = nullptr;    // [3] master's outward unit normal at the projection
  double gap = 0.0;                  // signed gap, m (< 0: penetration)
  double area = 0.0;                 // slave tributary area A_I, m^2
  double normal_force = 0.0;         // the penalty force on the node this step (pass factor included), N
};

/// The contact axis of contact_radius_max, when the deck sets one.
struct Axis {
  bool set = false;
  double point[3] = {0.0, 0.0, 0.0};
  double direction[3] = {0.0, 0.0, 1.0};  // unit
};

/// Slave-node / master-face pairs that carry a tangential force this pass (junction, Coulomb),
/// recorded by the law at each point and updated together after the normal forces (tangential_pairs.hpp).
/// Sized once for every slave node: recording never allocates.
struct TangentialPairs {
  int count = 0;
  std::vector<int> slave, face;        // slave index k, master face
  std::vector<double> shape, normal;   // [4], [3] per pair
  std::vector<double> normal_force;    // the node's normal force when recorded, N
  std::vector<double> vt, vpred;       // [3] v_t^{n+1/2} and the predicted v_t without the shear
  std::vector<double> share;           // [slave node] in-contact part of its tributary area (junction), m^2
  void size_for(std::size_t slave_nodes);
  void record(const ContactPoint& p);
};

/// m_eff = m_s m_M / (m_s + m_M), 1/m_M = sum_a N_a^2 / m_a (docs/theory.md 5.2), kg, from the lumped
/// masses `mass` [node].
inline double effective_mass(const std::vector<double>& mass, const ContactPoint& p) {
  double inv_mM = 0.0;
  for (int a = 0; a < 4; ++a) inv_mM += p.shape[a] * p.shape[a] / mass[p.face_nodes[a]];
  const double ms = mass[p.node], mM = 1.0 / inv_mM;
  return ms * mM / (ms + mM);
}

/// Scratch that takes the totals of the slave nodes another rank reports (PassView::totals_of).
struct UncountedTotals {
  ContactTotals totals;
  double friction[3] = {0.0, 0.0, 0.0};
  double stable_dt = 0.0;
};

struct PassView {
  const ContactSurface& slave;
  const ContactSurface& master;
  const double* x;              // positions [node][3], m
  const double* v;              // v^{n+1/2} [node][3], m/s (may be null)
  const double* other_force;    // non-contact forces of the coming update [node][3], N (may be null)
  double dt;                    // the coming step, s
  const std::vector<double>& mass;  // lumped masses [node], kg
  const std::vector<char>& prescribed;  // [node] velocity prescribed in x, y, z (may be empty: none)
  double* force;                // contact forces [node][3], N (added to)
  double* traction;             // nodal traction output [node][3], Pa
  double* status;               // nodal contact status [node] (1: in contact)
  ContactTotals& totals;
  double* friction;             // [3] vector sum of shear forces on the first slave surfaces, N
  double factor;                // pass factor: 1/2 for each pass of a symmetric interaction
  bool primary;                 // the first pass of its interaction
  double margin;                // search margin, m
  const Axis& axis;
  TangentialPairs& pairs;
  std::vector<double>& master_share;  // [node] scratch, zero between uses
  std::span<const double> gap;  // [slave node] this pass's gaps (NaN: no projection)
  double* state;                // the law's state [slave node][state_size] (n -> n+1 in place)
  double& stable_dt;            // the pass's critical time step (min over the law's contributions), s
  // Distributed runs (ContactManager::distribute): the slave nodes whose totals, friction and stable
  // step this rank reports; the others' go to `uncounted` and are dropped. nullptr: every node counts.
  const char* counted;          // [node]
  UncountedTotals* uncounted;
  // Owner computes (ContactManager::owner_computes) with tangential pairs: other ranks' pairs load
  // this rank's nodes too, so the pair prediction completes the forces and master shares over the
  // ranks into the scratch rows `completed` [node][4] (force, share) first. nullptr: a serial or
  // redundant run.
  ContactReductions* completion;
  double* completed;

  bool counts(int node) const { return counted == nullptr || counted[node] != 0; }
  /// Where a contribution of slave node `node` to the totals goes.
  ContactTotals& totals_of(int node) const { return counts(node) ? totals : uncounted->totals; }
  double* friction_of(int node) const { return counts(node) ? friction : uncounted->friction; }
  double& stable_dt_of(int node) const { return counts(node) ? stable_dt : uncounted->stable_dt; }

  /// Force f [3] on the slave node and -N_a f on the master face nodes; the node's traction.
  void apply(const ContactPoint& p, const double f[3]) const {
    for (int i = 0; i < 3; ++i) {
      force[3 * p.node + i] += f[i];
      for (int a = 0; a < 4; ++a) force[3 * p.face_nodes[a] + i] -= p.shape[a] * f[i];
      traction[3 * p.node + i] += f[i] / p.area;
    }
  }
  /// The node in contact: status, contact area (unless the law counts it otherwise), node count, radius.
  void count_contact(const ContactPoint& p, bool count_area) const;
  bool is_prescribed(int node) const { return !prescribed.empty() && prescribed[node]; }
  /// The point's m_eff from the run's (possibly mass-scaled) masses, kg.
  double effective_mass(const ContactPoint& p) const { return contact::effective_mass(mass, p); }
};

}  // namespace tribex::contact
