// SPDX-License-Identifier: MIT
// `model = junction`: the adhesion law plus the junction shear tau* tanh(|v_t|/v_ref) on the
// in-contact part of each slave node's area (docs/theory.md 7; models/junction_shear.hpp). Every node
// near the master is a candidate pair; its share of the contact area, int over {g <= g_j} of N_I dA
// with the gap interpolated bilinearly over each slave face, decides whether it carries shear (a node
// just outside g_j can own part of a face in contact), and the shares are the reported contact area.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "contact/laws/adhesion.hpp"
#include "contact/node_to_face/tangential_pairs.hpp"

namespace tribex::contact {

/// The in-contact part of each slave node's tributary area (shares in view.pairs.share), m^2: the
/// nodal gaps interpolated bilinearly over each slave face (nodes without a projection count as
/// far) and the contact indicator sampled at 8 x 8 midpoints; faces with all four nodes in contact
/// give A_f / 4 per node (exact for parallelograms) without sampling. Reference face areas, like A_I.
void contact_shares(PassView& view, double gap_tolerance);

struct Junction {
  Adhesion adhesion;
  JunctionLaw shear;

  static constexpr std::string_view deck_name = "junction";
  static constexpr std::array<KeyDecl, 6> keys{
      Adhesion::work_key, Adhesion::z0_key, Adhesion::cutoff_key,
      KeyDecl{"junction strength", "Pa", 0.0, true, true, "tau*, the junction shear strength"},
      KeyDecl{"junction reference speed", "m/s", 0.0, true, false,
             "v_ref of tau* tanh(|v_t|/v_ref) (default 0.1 m/s; no stability floor: backward Euler)"},
      KeyDecl{"junction gap tolerance", "m", 0.0, false, false, "a node is in contact when gap <= this (default 0.05 z0)"}};
  static constexpr bool penalty = true;
  static constexpr bool mortar = false;
  static constexpr bool area_from_shares = true;  // the pass does not count penalty nodes' areas
  static constexpr int state_size = 0;
  static constexpr double default_reference_speed = 0.1;  // m/s

  static std::optional<LawProblem> check(const KeyValues& v) { return Adhesion::check(v); }
  static Junction make(const KeyValues& v) {
    Junction j;
    j.adhesion = Adhesion::make(v);
    j.shear.strength = v.get("junction strength", 0.0);
    j.shear.reference_speed = v.get("junction reference speed", default_reference_speed);
    j.shear.gap_tolerance = j.adhesion.gap_tolerance;
    return j;
  }
  std::string describe() const {
    return adhesion.describe() + format_line("; junction strength tau* = %.4g Pa, reference speed %.4g m/s (tanh law, "
                                             "backward Euler per pair: no stability floor)",
                                             shear.strength, shear.reference_speed);
  }
  double reach() const { return adhesion.reach(); }
  const Adhesion* adhesion_part() const { return &adhesion; }

  void at_point(const ContactPoint& p, PassView& view) const {
    adhesion.adhere(p, view, false);
    view.pairs.record(p);
  }
  /// The shear on the pairs that own contact area (tangential_pairs.hpp), after the normal forces.
  void end_pass(PassView& view) const {
    TangentialPairs& q = view.pairs;
    if (!view.v) {
      q.count = 0;
      return;
    }
    contact_shares(view, shear.gap_tolerance);
    int count = 0;  // keep the pairs that own contact area
    for (int j = 0; j < q.count; ++j) {
      const double share = q.share[q.slave[j]];
      view.totals_of(view.slave.nodes[q.slave[j]]).area += view.factor * share;
      if (!(share > 0.0)) continue;
      q.slave[count] = q.slave[j];
      q.face[count] = q.face[j];
      for (int a = 0; a < 4; ++a) q.shape[4 * count + a] = q.shape[4 * j + a];
      for (int i = 0; i < 3; ++i) q.normal[3 * count + i] = q.normal[3 * j + i];
      ++count;
    }
    q.count = count;
    shear_pairs(view, shear, [&](int j, double) {
      const double capacity = view.factor * shear.strength * q.share[q.slave[j]];
      view.totals_of(view.slave.nodes[q.slave[j]]).junction_capacity += capacity;
      return capacity;
    });
  }
};

}  // namespace tribex::contact
