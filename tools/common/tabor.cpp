// SPDX-License-Identifier: MIT
// docs/theory.md 8.5 (mu_T) and 6.7.8 (where DMT and JKR stop holding for the Lennard-Jones law).
#include "tools/common/tabor.hpp"

#include <cmath>
#include <cstdio>

namespace tribex::tools {

double tabor_parameter(double radius, double work, double e_star, double z0) {
  return std::cbrt(radius * work * work / (e_star * e_star * z0 * z0 * z0));
}

std::string regime_text(AdhesionRegime r) {
  char b[64];
  if (r == AdhesionRegime::dmt) std::snprintf(b, sizeof b, "DMT (mu_T <= %g)", dmt_max_tabor);
  else std::snprintf(b, sizeof b, "JKR (mu_T >= %g)", jkr_min_tabor);
  return b;
}

std::string regime_warning(AdhesionRegime r, double tabor, const std::string& who, const std::string& where,
                           const std::string& advice) {
  const bool dmt = r == AdhesionRegime::dmt;
  if (!(tabor > 0) || (dmt ? tabor <= dmt_max_tabor : tabor >= jkr_min_tabor)) return "";
  char b[512];
  std::snprintf(b, sizeof b,
                "warning: %s assumes %s but mu_T = %.3g (%s): the pull-off there lies between 1.5 and 2 pi W R and %s "
                "(tools/adhesion/README.md); %s",
                who.c_str(), regime_text(r).c_str(), tabor, where.c_str(),
                dmt ? "below the DMT 2 pi W R" : "above the JKR 1.5 pi W R", advice.c_str());
  return b;
}

}  // namespace tribex::tools
