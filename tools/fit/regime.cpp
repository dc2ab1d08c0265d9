// SPDX-License-Identifier: MIT
// docs/theory.md 8.5 and 6.7.8: the Tabor parameter of a fit and the regime its model assumes.
#include "tools/fit/regime.hpp"

#include <cstdio>

namespace tribex::fit {

RegimeCheck check_regime(const FrictionModel& model, const FrictionParams& best) {
  const auto& s = model.setup();
  RegimeCheck c;
  c.z0 = s.md_z0.value_or(0.3e-9);
  c.e_star = model.reduced_modulus();
  c.basis = "E* of the uncoated contact";
  switch (s.model) {
    case AreaModel::dmt: c.regime = tools::AdhesionRegime::dmt; break;
    case AreaModel::jkr: c.regime = tools::AdhesionRegime::jkr; break;
    case AreaModel::coated: {
      c.regime = tools::AdhesionRegime::dmt;
      const double ebar_c = best.coating_youngs / (1 - s.coating_poisson * s.coating_poisson);
      c.e_star = 1.0 / (1.0 / model.plane_strain_modulus() + 1.0 / ebar_c);
      c.basis = "E* of the tip on the coating alone (thick-coating bound)";
      break;
    }
    default: break;
  }
  char where[200];
  if (s.model == AreaModel::maugis_dugdale && s.md_lambda) {
    c.tabor = *s.md_lambda / 1.157;
    c.basis = "lambda/1.157";
  } else if (best.work_of_adhesion > 0) {
    c.tabor = tools::tabor_parameter(s.radius, best.work_of_adhesion, c.e_star, c.z0);
  }
  c.basis += s.md_z0 ? ", z0 from --z0" : ", z0 = 0.3 nm (--z0 to set)";
  if (c.regime) {
    std::snprintf(where, sizeof where, "R = %.3g nm, fitted W = %.3g J/m^2, E* = %.3g GPa, z0 = %.3g nm", s.radius * 1e9,
                  best.work_of_adhesion, c.e_star * 1e-9, c.z0 * 1e9);
    const char* advice = s.model == AreaModel::coated
                             ? "Eq. 3.1 has no transition form: compare its pull-off with tribex adhesion-curve at this mu_T"
                             : "use --model md (or cos), or compare with tribex adhesion-curve";
    c.warning = tools::regime_warning(*c.regime, c.tabor, "tribex fit --model " + model_name(s.model), where, advice);
  }
  return c;
}

}  // namespace tribex::fit
