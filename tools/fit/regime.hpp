// SPDX-License-Identifier: MIT
// The adhesion regime each contact-area model of `tribex fit` assumes, and the Tabor parameter of the
// fitted contact (docs/theory.md 8.5, 9; issue 53 scope 3): dmt and coated (Eq. 3.1's L + 2 pi R W
// is the DMT carried load) assume DMT, jkr assumes JKR, cos and md cover the transition.
#pragma once

#include <optional>
#include <string>

#include "tools/common/tabor.hpp"
#include "tools/fit/friction_model.hpp"

namespace tribex::fit {

struct RegimeCheck {
  std::optional<tools::AdhesionRegime> regime;  // none for cos and md
  double tabor = 0;    // of the fitted W (0 when W <= 0)
  double e_star = 0;   // the modulus used, Pa
  double z0 = 0;       // m
  std::string basis;   // how E* and z0 were chosen, for the report
  std::string warning; // "" inside the regime, else one line
};

/// z0 = --z0 when given, else 0.3 nm (the verification decks' value). coated: E* of the tip on the
/// coating alone, 1/E* = 1/Ebar + 1/Ebar_c (a thick coating: the upper bound of mu_T). md with
/// --lambda: mu_T = lambda/1.157 (docs/theory.md 8.5).
RegimeCheck check_regime(const FrictionModel& model, const FrictionParams& best);

}  // namespace tribex::fit
