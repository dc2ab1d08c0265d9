// SPDX-License-Identifier: MIT
// The Tabor parameter of a sphere-flat adhesive contact and the one-line warning of a tool whose
// model assumes the DMT or the JKR end (docs/theory.md 8.5, 6.7.8; issue 53 scope 3). The limits are
// where the Lennard-Jones reference (tools/adhesion/README.md, regression table) leaves the assumed
// end's pull-off by several per cent: 1.86 pi W R at mu_T = 0.3 (DMT: 2, -7 %), 1.54 at mu_T = 3 (JKR:
// 1.5, +3 %). tools/python/contact_theory.py holds the same numbers for the Python scripts.
#pragma once

#include <string>

namespace tribex::tools {

inline constexpr double dmt_max_tabor = 0.3;  // DMT assumed: warn above
inline constexpr double jkr_min_tabor = 3.0;  // JKR assumed: warn below

/// mu_T = (R W^2/(E*^2 z0^3))^(1/3); R, W, E*, z0 > 0 (SI).
double tabor_parameter(double radius, double work, double e_star, double z0);

enum class AdhesionRegime { dmt, jkr };

/// The regime as one phrase, e.g. "DMT (mu_T <= 0.3)".
std::string regime_text(AdhesionRegime r);

/// "" when `tabor` lies in the regime `r`; else one line (no newline): "warning: WHO assumes ... but
/// mu_T = X (WHERE): ...; ADVICE" (ADVICE: what covers the transition, e.g. "use tribex adhesion-curve").
std::string regime_warning(AdhesionRegime r, double tabor, const std::string& who, const std::string& where,
                           const std::string& advice);

}  // namespace tribex::tools
