// SPDX-License-Identifier: MIT
// The tangential force on the pairs a law recorded in a pass (junction shear, Coulomb friction), taken
// backward Euler per pair (docs/theory.md 7.3; contact/models/junction_shear.hpp). Per pair, with the
// relative velocity v_r = v_slave - sum_a N_a v_a and its tangential part v_t:
//  - the predicted v_t at n+3/2 without the shear: v^{n+1/2} + dt (other + contact normal forces) / m,
//    node by node, then the same relative tangential projection;
//  - the pair mass: a shear F on the slave and -N_a F on the master nodes changes v_r by
//    dt F (1/m_s + sum_a N_a^2 / m_a) when the pair is alone; with every pair loaded at once a master
//    node a takes sum_b N_a(b) F_b, so the row sum 1/m_pair = 1/m_s + sum_a N_a S_a / m_a with
//    S_a = sum over pairs of N_a bounds the coupled change (Gershgorin): the simultaneous
//    backward-Euler updates under-relax rather than overshoot. For one pair S_a = N_a.
//  - F from junction_update with the law's capacity (N, pass factor included), capped at the stick
//    force m_pair |v_pred| / dt.
// Nodes whose velocity is prescribed in all three components (ContactManager::set_prescribed_nodes)
// keep their velocity in the prediction and take no share of the pair mass, so a pair on a fixed
// master sticks exactly; partly constrained nodes count as free (the update under-relaxes, stable).
#pragma once

#include "contact/models/junction_shear.hpp"
#include "contact/node_to_face/pass_view.hpp"

namespace tribex::contact {

/// Trial (Jacobi) velocities of every recorded pair, v_t and v_pred, and the master shares S_a.
void predict_pair_velocities(PassView& view);
/// The pair mass of pair j (pass factor included), kg; after predict_pair_velocities.
double pair_mass(const PassView& view, int j);
/// Applies the update of pair j: forces, traction, friction vector and power.
void apply_pair_update(PassView& view, int j, const JunctionUpdate& up);
/// Zeroes the master shares and empties the pair list.
void end_pairs(PassView& view);

/// The shear of every recorded pair: `capacity(j, m_pair)` gives pair j's force cap (N, pass factor
/// included) and may update the law's state; `speed` the tanh regularisation v_ref (0: exact stick).
template <class Capacity>
void shear_pairs(PassView& view, const JunctionLaw& speed, Capacity&& capacity) {
  predict_pair_velocities(view);
  TangentialPairs& q = view.pairs;
  for (int j = 0; j < q.count; ++j) {
    const double m_pair = pair_mass(view, j);
    if (!(m_pair > 0.0)) continue;  // both sides prescribed
    const JunctionUpdate up = junction_update(&q.vt[3 * j], &q.vpred[3 * j], capacity(j, m_pair), m_pair, view.dt, speed);
    apply_pair_update(view, j, up);
  }
  end_pairs(view);
}

}  // namespace tribex::contact
