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
  large_strain,     // a small-strain elastic block's largest principal strain above small_strain_warning
  scaled_silent_boundary,  // set-up: a silent boundary on mass-scaled elements (it reflects)
};

/// The name written to summary.json and the log ("energy_error", ...).
const char* kind_name(WarningKind kind);

/// The energy ledger's term an energy-balance warning names as its likely source (RunGuards: the
/// largest change of the contact and dissipation terms since the error was last below half the warning).
enum class EnergySource { none, contact, hourglass, viscous, damping, silent_boundary, plastic, kinetic };

/// The name written to summary.json ("contact_work", ...; "" for none).
const char* source_name(EnergySource source);

struct RunWarning {
  WarningKind kind = WarningKind::energy_error;
  long step = 0;           // first crossing (set-up warnings: the first step)
  double time = 0.0;       // s
  double value = 0.0;      // the watched quantity there (dimensionless ratio)
  double threshold = 0.0;  // the bound it crossed
  double max_value = 0.0;  // largest value over the run (or the window checked)
  long max_step = 0;
  double max_time = 0.0;   // s
  int node = -1;           // global node (0-based) the value was measured at, -1: none (large_strain: the element)
  int block = -1;          // large_strain: the block (index in the model's blocks), -1: none
  // energy_error only: the likely source, its term's change since `since_step` (J; the contact's: the
  // energy it gave the bodies, so positive when it injected) and the step the error was last below half
  // the warning.
  EnergySource source = EnergySource::none;
  double source_change = 0.0;
  long since_step = 0;
  std::string message;     // one line: what, where, and what to change
};

/// What the set-up hands the run guards: warnings to report at once, and choices that are unsafe only
/// under some load, watched during the run.
struct SetupFindings {
  std::vector<RunWarning> warnings;
  // Node-to-face penalty contact on one-point (mean_quadrature) elements, "interaction 'i' on block
  // 'a', 'b'" (empty: none): raised as unsafe_choice when the contact penetration shows high pressure.
  std::string one_point_contact;
  // The contact interactions ("'a', 'b'"), for the energy warning's source; empty without contact.
  std::string contact_interactions;
  bool mass_scaled = false;  // `begin mass scaling`: the energy warning's contact hint names the surfaces' raise
  std::vector<std::string> block_names;  // the model's blocks, in order (the large_strain warning names one)
};

}  // namespace tribex::solver
