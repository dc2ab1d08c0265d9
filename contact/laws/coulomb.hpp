// SPDX-License-Identifier: MIT
// `model = coulomb`: penalty contact with Coulomb friction (docs/theory.md 7.5), optionally with the
// Lennard-Jones adhesion law of `model = adhesion` (give `work of adhesion` and `equilibrium separation`).
// On every penetrating slave node the friction force opposes the relative tangential velocity and is
// at most mu N, N the node's normal force (the penalty force; adhesion acts on the nodes around it,
// so the friction follows the net load N_applied + F_adh, Derjaguin). A stuck node stays stuck while
// the force that holds it, m_pair |v_pred| / dt, is at most mu_s N; it then slides with mu_k N until
// the kinetic force would stop it within a step. Each step's force is the backward-Euler pair update
// of the junction law (node_to_face/tangential_pairs.hpp) with capacity mu N: exact stick (no creep)
// with `friction reference speed` 0, the default; v_ref > 0 regularises the stick as mu N tanh(|v_t|/v_ref).
// The friction power enters friction_work, so the energy balance counts the dissipated work.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "contact/laws/adhesion.hpp"
#include "contact/node_to_face/tangential_pairs.hpp"

namespace tribex::contact {

struct Coulomb {
  double static_coefficient = 0.0;   // mu_s
  double kinetic_coefficient = 0.0;  // mu_k <= mu_s
  JunctionLaw speed;                 // reference_speed: v_ref of the regularisation (0: exact stick), m/s
  bool adhesive = false;
  Adhesion adhesion;                 // when `work of adhesion` is given

  static constexpr std::string_view deck_name = "coulomb";
  static constexpr std::array<KeyDecl, 6> keys{{
      {"static friction coefficient", "", 0.0, true, true, "mu_s: a node sticks while its tangential force is at most mu_s N"},
      {"kinetic friction coefficient", "", 0.0, false, false, "mu_k <= mu_s: the sliding force mu_k N (default mu_s)"},
      {"friction reference speed", "m/s", 0.0, false, false,
       "v_ref of the regularised stick mu N tanh(|v_t|/v_ref) (default 0: exact stick)"},
      optional_key(Adhesion::work_key), optional_key(Adhesion::z0_key), Adhesion::cutoff_key}};
  static constexpr bool penalty = true;
  static constexpr bool mortar = false;
  static constexpr int state_size = 1;  // 1: the node slid in its last step in contact, 0: stuck

  static std::optional<LawProblem> check(const KeyValues& v) {
    const double mu_s = v.get("static friction coefficient", 0.0);
    if (v.get("kinetic friction coefficient", mu_s) > mu_s)
      return LawProblem{"kinetic friction coefficient",
                        "'kinetic friction coefficient' must not exceed 'static friction coefficient'; lower it"};
    if (v.has("work of adhesion") != v.has("equilibrium separation"))
      return LawProblem{v.has("work of adhesion") ? "work of adhesion" : "equilibrium separation",
                        "adhesion with 'model = coulomb' needs both 'work of adhesion' and 'equilibrium separation'; "
                        "add the other or remove this one"};
    if (v.has("adhesion cutoff") && !v.has("work of adhesion"))
      return LawProblem{"adhesion cutoff", "'adhesion cutoff' needs 'work of adhesion' and 'equilibrium separation'; "
                                           "add them or remove the key"};
    return Adhesion::check(v);
  }
  static Coulomb make(const KeyValues& v) {
    Coulomb c;
    c.static_coefficient = v.get("static friction coefficient", 0.0);
    c.kinetic_coefficient = v.get("kinetic friction coefficient", c.static_coefficient);
    c.speed.reference_speed = v.get("friction reference speed", 0.0);
    c.adhesive = v.has("work of adhesion");
    if (c.adhesive) c.adhesion = Adhesion::make(v);
    return c;
  }
  std::string describe() const {
    const std::string line = format_line("Coulomb friction mu_s = %.4g, mu_k = %.4g, %s", static_coefficient,
                                         kinetic_coefficient,
                                         speed.reference_speed > 0.0 ? "stick regularised" : "exact stick");
    return adhesive ? line + "; " + adhesion.describe() : line;
  }
  double reach() const { return adhesive ? adhesion.reach() : 0.0; }
  const Adhesion* adhesion_part() const { return adhesive ? &adhesion : nullptr; }

  void at_point(const ContactPoint& p, PassView& view) const {
    if (adhesive) adhesion.adhere(p, view, true);
    if (p.gap < 0.0 && p.normal_force > 0.0) view.pairs.record(p);
  }
  void end_pass(PassView& view) const {
    TangentialPairs& q = view.pairs;
    if (!view.v) {
      q.count = 0;
      return;
    }
    // state + 2 marks the nodes updated this step; the others (out of contact) return to stuck.
    shear_pairs(view, speed, [&](int j, double m_pair) {
      double& sliding = view.state[q.slave[j]];
      const double* vp = &q.vpred[3 * j];
      const double hold = m_pair * std::sqrt(vp[0] * vp[0] + vp[1] * vp[1] + vp[2] * vp[2]) / view.dt;
      const double N = q.normal_force[j];
      const bool slides = sliding > 0.0 ? hold > kinetic_coefficient * N : hold > static_coefficient * N;
      sliding = slides ? 3.0 : 2.0;
      return (slides ? kinetic_coefficient : static_coefficient) * N;
    });
    for (int k = 0; k < view.slave.node_count(); ++k) view.state[k] = view.state[k] > 2.5 ? 1.0 : 0.0;
  }
};

}  // namespace tribex::contact
