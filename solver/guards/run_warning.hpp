// SPDX-License-Identifier: MIT
// One entry of a run's warnings list (summary.json "warnings", log.txt, the terminal): what went
// physically wrong or is known to be unsafe, where in the run it first happened and how far it went.
#pragma once

#include <string>
#include <vector>

namespace tribex::solver {

enum class WarningKind {
  energy_error,     // |energy balance| / largest energy above `energy error warning`
  penetration,      // contact penetration / local element size above `penetration warning`
  kinetic_energy,   // quasi static: kinetic / internal energy above `kinetic energy warning` while loaded
  contact_motion,   // one-step surface motion / capture distance above `contact motion warning`
  adhesion_cutoff,  // set-up: the adhesion law's cut-off keeps less than 99 % of W
  unsafe_choice,    // a choice known to be unsafe, once the run reaches where it is (see SetupFindings)
};

/// The name written to summary.json and the log ("energy_error", ...).
const char* kind_name(WarningKind kind);

struct RunWarning {
  WarningKind kind = WarningKind::energy_error;
  long step = 0;           // first crossing (set-up warnings: the first step)
  double time = 0.0;       // s
  double value = 0.0;      // the watched quantity there (dimensionless ratio)
  double threshold = 0.0;  // the bound it crossed
  double max_value = 0.0;  // largest value over the run (or the window checked)
  long max_step = 0;
  double max_time = 0.0;   // s
  int node = -1;           // global node (0-based) the value was measured at, -1: none
  std::string message;     // one line: what, where, and what to change
};

/// What the set-up hands the run guards: warnings to report at once, and choices that are unsafe only
/// under some load, watched during the run.
struct SetupFindings {
  std::vector<RunWarning> warnings;
  // Node-to-face penalty contact on one-point (mean_quadrature) elements, "interaction 'i' on block
  // 'a', 'b'" (empty: none): raised as unsafe_choice when the contact penetration shows high pressure.
  std::string one_point_contact;
};

}  // namespace tribex::solver
