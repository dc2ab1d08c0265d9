// SPDX-License-Identifier: MIT
// The attraction of the non-contacting part of a rough surface across its local gaps (issue 26;
// docs/theory.md 10.8), the term that gives a near-constant adhesive offset F = mu (N + F_adh)
// between nominally flat surfaces (report Section 2.1.3, Eq. 2.2), where the DMT pull of the
// contacting asperities (Eq. 4.10) grows with the load.
//
// The surface heights z (about the mean plane the separation d is measured from) are Gaussian with
// deviation sigma. A point at height z < d faces the counterface across the local gap g = d - z and
// attracts it with the asperity-scale Lennard-Jones law of docs/theory.md 6 (the same W, its own z0,
// the cut-off h_c and the continuity shift: `adhesive_traction(g)`); points with z >= d touch and are
// the asperity contacts of the GW law (excluded here). Per unit nominal area, attraction positive:
//   p_nc(d)     = int_0^{g_c} sigma_s(g + z0) phi((d - g)/sigma) / sigma dg,
//   dp_nc/dd    = int_0^{g_c} sigma_s(g + z0) phi'((d - g)/sigma) / sigma^2 dg,   phi'(x) = -x phi(x),
// g_c = h_c - z0. Far from contact (d >> sigma) it is the flat-flat law sigma_s(d + z0); for z0 << g it
// falls as 8 W z0^2 / (3 g^3), the Hamaker form A_H / (6 pi g^3) with A_H = 16 pi W z0^2.
// Tabulated once in d (cubic Hermite with the exact derivative), zero beyond d = g_c + 8 sigma.
#pragma once

#include <vector>

#include "contact/models/adhesion_lj.hpp"

namespace tribex::contact {

class NoncontactAttraction {
 public:
  NoncontactAttraction() = default;
  /// `law` the local Lennard-Jones law (W, z0, h_c); `sigma` the deviation of the surface heights, m.
  NoncontactAttraction(const AdhesionLaw& law, double sigma);

  bool active() const { return sigma_ > 0.0; }
  struct Value {
    double pressure = 0.0;   // attraction p_nc, Pa (>= 0 pulls the surfaces together)
    double slope = 0.0;      // dp_nc/dd, Pa/m
  };
  /// From the table (what the step loop calls).
  Value evaluate(double d) const;
  /// By quadrature (the table's reference; too slow for the step loop).
  Value evaluate_direct(double d) const;
  /// Beyond this mean-plane separation the attraction is zero, m.
  double reach() const { return d_max_; }
  const AdhesionLaw& law() const { return law_; }
  double sigma() const { return sigma_; }

 private:
  AdhesionLaw law_;
  double sigma_ = 0.0;
  double d_min_ = 0.0, d_max_ = 0.0, spacing_ = 0.0;
  std::vector<double> p_, dp_;
};

}  // namespace tribex::contact
