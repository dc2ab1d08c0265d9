// SPDX-License-Identifier: MIT
// The sums one time-n accounting makes over this rank's nodes and elements (CentralDifference::
// account_time_n), reduced over the ranks in one message. The table below is the message's layout:
// a new energy term is one member and one row (docs/theory.md 1.3, "Energy bookkeeping", for the pairings).
#pragma once

#include <array>

namespace tribex::solver {

struct StepSums {
  double kinetic = 0.0;                                       // J, shadow KE^n = (1/2) v^{n-1/2} . M v^{n+1/2}
  double momentum_x = 0.0, momentum_y = 0.0, momentum_z = 0.0;  // kg m/s, sum m v^n
  // Each trapezoidal term as its two halves, F^n . v^{n-1/2} (left) and F^n . v^{n+1/2} (right), W:
  double external_left = 0.0, external_right = 0.0;  // reactions and applied loads
  double contact_left = 0.0, contact_right = 0.0;    // contact forces on the bodies
  double silent_left = 0.0, silent_right = 0.0;      // silent-boundary dashpots
  double damping_left = 0.0, damping_right = 0.0;    // mass damping, per unit damping coefficient
  double internal = 0.0, hourglass = 0.0;            // J, this force pass's stored energies
  double viscous_power = 0.0;                        // W, element viscosity of the last force pass (left half)
  double viscous_right = 0.0;                        // W, its forces F_v^n . v^{n+1/2} (the right half)
  double plastic_work = 0.0;                         // J, material dissipation so far
};

/// The reduction's layout: every member of StepSums once.
inline constexpr std::array<double StepSums::*, 17> step_sum_fields = {
    &StepSums::kinetic,       &StepSums::momentum_x,     &StepSums::momentum_y,   &StepSums::momentum_z,
    &StepSums::external_left, &StepSums::external_right, &StepSums::contact_left, &StepSums::contact_right,
    &StepSums::silent_left,   &StepSums::silent_right,   &StepSums::damping_left, &StepSums::damping_right,
    &StepSums::internal,      &StepSums::hourglass,      &StepSums::viscous_power, &StepSums::plastic_work,
    &StepSums::viscous_right};
static_assert(sizeof(StepSums) == step_sum_fields.size() * sizeof(double), "a StepSums member without a row");

}  // namespace tribex::solver
