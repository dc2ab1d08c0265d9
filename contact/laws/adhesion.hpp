// SPDX-License-Identifier: MIT
// `model = adhesion`: penalty contact plus the Lennard-Jones attraction (docs/theory.md 6;
// models/adhesion_lj.hpp). On every slave node with 0 <= g <= g_c = h_c - z0, the traction
// sigma_s(g + z0) A_I toward the master face, reactions -N_a F on the master; the node counts as in
// contact when g <= g_j (penalty contact g < 0 is counted by the pass). The mortar enforcement
// integrates the same law at face points (contact/mortar/).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "contact/laws/law_key.hpp"
#include "contact/models/adhesion_lj.hpp"
#include "contact/node_to_face/pass_view.hpp"

namespace tribex::contact {

struct Adhesion {
  AdhesionLaw lj;
  double gap_tolerance = 0.0;  // g_j: in contact when g <= g_j, m
  bool default_cutoff = true;  // h_c not given in the deck (for the log)

  static constexpr std::string_view deck_name = "adhesion";
  // The default cut-off h_c = 20 z0 keeps 99.03 % of W (docs/theory.md 6.3; 5 z0 keeps 86.1 %, 10 z0 96.3 %).
  static constexpr double default_cutoff_in_z0 = 20.0;
  static constexpr double default_gap_tolerance_in_z0 = 0.05;
  // W >= 0: with W = 0 the traction sigma_a (docs/theory.md 6.1, proportional to W) vanishes and the
  // penalty contact alone remains, repulsive only (the W = 0 member of a sweep; tests/params: the same
  // history as `model = frictionless`, bit for bit).
  static constexpr KeyDecl work_key{"work of adhesion", "J/m^2", 0.0, false, true,
                                    "W of the Lennard-Jones adhesion law (0: no attraction, penalty contact only)"};
  static constexpr KeyDecl z0_key{"equilibrium separation", "m", 0.0, true, true, "z0 of the Lennard-Jones adhesion law"};
  static constexpr KeyDecl cutoff_key{"adhesion cutoff", "m", 0.0, true, false,
                                     "cut-off separation h_c, measured like h = gap + z0, > z0 (default 20 z0: keeps 99 % of W)"};
  static constexpr std::array<KeyDecl, 3> keys{work_key, z0_key, cutoff_key};
  static constexpr bool penalty = true;
  static constexpr bool mortar = true;
  static constexpr int state_size = 0;
  static constexpr bool reads_velocity = false;

  static std::optional<LawProblem> check(const KeyValues& v) {
    const auto cutoff = v.find("adhesion cutoff"), z0 = v.find("equilibrium separation");
    if (cutoff && z0 && !(*cutoff > *z0))
      return LawProblem{"adhesion cutoff", "'adhesion cutoff' is the cut-off separation h_c (measured like h = gap + z0) "
                                           "and must exceed 'equilibrium separation' z0; use e.g. 5 z0"};
    return std::nullopt;
  }
  static Adhesion make(const KeyValues& v) {
    Adhesion a;
    a.lj.work = v.get("work of adhesion", 0.0);
    a.lj.z0 = v.get("equilibrium separation", 0.0);
    a.default_cutoff = !v.find("adhesion cutoff");
    a.lj.cutoff = v.get("adhesion cutoff", default_cutoff_in_z0 * a.lj.z0);
    a.gap_tolerance = v.get("junction gap tolerance", default_gap_tolerance_in_z0 * a.lj.z0);
    return a;
  }
  std::string describe() const {
    if (!(lj.work > 0.0))
      return format_line("adhesion W = 0: no attraction, penalty contact only (z0 = %.4g m, cutoff h_c = %.4g m unused)",
                         lj.z0, lj.cutoff);
    return format_line("adhesion W = %.4g J/m^2, z0 = %.4g m, cutoff h_c = %.4g m (%.3g z0%s), captured work %.4g "
                       "J/m^2 (%.2f %% of W), in contact when gap <= %.4g m",
                       lj.work, lj.z0, lj.cutoff, lj.cutoff / lj.z0, default_cutoff ? ", the default" : "",
                       captured_work(lj), 100.0 * captured_work(lj) / lj.work, gap_tolerance);
  }
  // W = 0 acts only through the penalty: no reach beyond it, so the search is frictionless contact's.
  double reach() const { return lj.work > 0.0 ? lj.capture_gap() : 0.0; }
  const Adhesion* adhesion_part() const { return this; }

  /// The adhesion at a point: potential energy, in-contact bookkeeping for 0 <= g <= g_j (area
  /// counted unless `count_area` is false), and the attraction for g >= 0.
  void adhere(const ContactPoint& p, PassView& view, bool count_area) const {
    view.totals_of(p.node).adhesion_energy += view.factor * p.area * adhesive_energy(p.gap, lj);
    if (p.gap <= gap_tolerance && p.gap >= 0.0) view.count_contact(p, count_area);  // g < 0: counted by the pass
    if (p.gap < 0.0) return;
    // Attraction: toward the master face, i.e. against its outward normal.
    const double fa = view.factor * adhesive_traction(p.gap, lj) * p.area;
    view.totals_of(p.node).adhesive_force += fa;
    const double f[3] = {-fa * p.normal[0], -fa * p.normal[1], -fa * p.normal[2]};
    view.apply(p, f);
  }
  void at_point(const ContactPoint& p, PassView& view) const { adhere(p, view, true); }
};

}  // namespace tribex::contact
