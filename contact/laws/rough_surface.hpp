// SPDX-License-Identifier: MIT
// `model = rough surface`: the homogenized Greenwood-Williamson law (docs/theory.md 10.3-10.5;
// models/rough_surface.hpp) replaces the penalty. At the mean-plane separation d = g + offset, the
// normal force p(d) A_I along the master's outward normal (p > 0 pushes apart), the junction shear
// tau* (A_c/A_0)(d) A_I (explicit tanh law) and the node's critical step: 2 sqrt(m_eff / (A_I dp/dd))
// for the normal spring, 2 m_eff v_ref / (tau* (A_c/A_0) A_I) for the shear damper.
// Summits: continuous Gaussian (density, radius, sigma_s) or a discrete file (height_m, radius_m per
// line) with the area of its map.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "contact/laws/law_key.hpp"
#include "contact/models/junction_shear.hpp"
#include "contact/models/rough_surface.hpp"
#include "contact/node_to_face/pass_view.hpp"

namespace tribex::contact {

struct RoughSurface {
  std::shared_ptr<const RoughSurfaceLaw> law;  // tabulated once, shared by the interaction's passes
  double mean_plane_offset = 0.0;              // d = g + offset, m
  JunctionLaw shear;                           // strength 0: frictionless
  std::string summit_file;                     // for the log

  static constexpr std::string_view deck_name = "rough surface";
  static constexpr double default_noncontact_cutoff_in_z0 = 200.0;
  static constexpr std::array<KeyDecl, 13> keys{{
      {"composite modulus", "Pa", 0.0, true, true, "E* = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2) of the asperity contacts"},
      {"summit density", "1/m^2", 0.0, true, false, "eta, summits per nominal area (or a summit file)"},
      {"summit radius", "m", 0.0, true, false, "R_s, mean summit radius (or a summit file)"},
      {"summit height deviation", "m", 0.0, true, false,
       "sigma_s, standard deviation of the summit heights (or a summit file)"},
      {"summit file", "path", 0.0, true, false, "discrete population: CSV height_m,radius_m per summit, relative to the deck"},
      {"summit map area", "m^2", 0.0, true, false, "area of the map the summit file came from"},
      {"mean plane offset", "m", -INFINITY, true, false, "d = gap + offset: mean-plane separation when the surfaces touch (default 0)"},
      {"work of adhesion", "J/m^2", 0.0, true, false, "W of DMT adhesion per asperity (default 0)"},
      {"junction strength", "Pa", 0.0, true, false, "tau* on the real area (default none: frictionless)"},
      {"junction reference speed", "m/s", 0.0, true, false, "v_ref of tau* tanh(|v_t|/v_ref) (default 0.1 m/s)"},
      {"noncontact equilibrium separation", "m", 0.0, true, false,
       "z0 of the attraction of the non-contacting area (on when given; needs W; docs/theory.md 10.8)"},
      {"noncontact cutoff", "m", 0.0, true, false, "h_c of the non-contact attraction, > its z0 (default 200 z0)"},
      {"surface height deviation", "m", 0.0, true, false,
       "sigma of the surface heights for the non-contact attraction (default: the summit height deviation)"},
  }};
  static constexpr bool penalty = false;  // the GW pressure is the whole normal law
  static constexpr bool mortar = false;
  static constexpr int state_size = 0;

  /// Continuous (the three summit keys) or discrete (summit file and its map area), not both.
  static std::optional<LawProblem> check(const KeyValues& v) {
    if (auto problem = check_noncontact(v)) return problem;
    const char* continuous_keys[] = {"summit density", "summit radius", "summit height deviation"};
    if (v.has("summit file")) {
      for (const char* k : continuous_keys)
        if (v.has(k))
          return LawProblem{k, std::string("'") + k + "' is taken from the summit file; remove it or remove 'summit file'"};
      if (!v.has("summit map area"))
        return LawProblem{"summit file",
                          "'summit file' needs 'summit map area' (area of the map the summits were found on, m^2); add it"};
      return std::nullopt;
    }
    if (v.has("summit map area"))
      return LawProblem{"summit map area", "'summit map area' belongs to 'summit file'; add the file or remove the key"};
    for (const char* k : continuous_keys)
      if (!v.has(k))
        return LawProblem{"", std::string("'model = rough surface' needs '") + k +
                                  "' (from `tribex surface stats`) or a 'summit file'; add it to the interaction"};
    return std::nullopt;
  }
  /// The non-contact attraction: its z0 switches it on and needs W and continuous summits.
  static std::optional<LawProblem> check_noncontact(const KeyValues& v) {
    const auto z0 = v.find("noncontact equilibrium separation");
    for (const char* k : {"noncontact cutoff", "surface height deviation"})
      if (v.has(k) && !z0)
        return LawProblem{k, std::string("'") + k + "' belongs to the non-contact attraction; add 'noncontact equilibrium "
                                                   "separation' or remove the key"};
    if (!z0) return std::nullopt;
    if (!(v.get("work of adhesion", 0.0) > 0.0))
      return LawProblem{"noncontact equilibrium separation",
                        "the non-contact attraction needs 'work of adhesion' (W of its Lennard-Jones law); add it"};
    if (v.has("summit file"))
      return LawProblem{"noncontact equilibrium separation",
                        "the non-contact attraction needs the continuous summit statistics, not a 'summit file'"};
    if (const auto cutoff = v.find("noncontact cutoff"); cutoff && !(*cutoff > *z0))
      return LawProblem{"noncontact cutoff", "'noncontact cutoff' must exceed 'noncontact equilibrium separation'"};
    return std::nullopt;
  }
  /// Reads the summit file (LawError naming FILE:LINE) and tabulates the law.
  static RoughSurface make(const KeyValues& v);
  std::string describe() const;
  /// Beyond this gap the law is zero: its reach (contact separation, or the non-contact attraction's)
  /// minus the offset, m.
  double reach() const { return law->reach() - mean_plane_offset; }

  void at_point(const ContactPoint& p, PassView& view) const;
};

}  // namespace tribex::contact
