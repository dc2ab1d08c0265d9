// SPDX-License-Identifier: MIT
// The 1-D oscillator of the dynamic-friction test (report Section 2.1.6):
//
//     m x'' + c x' + k (x - x_eq) = -F_d sign(x')        (Coulomb friction plus air damping)
//
// and sticking at a velocity zero when the spring force |k (x - x_eq)| <= F_s (static friction).
// Divided by m it depends only on omega0 = sqrt(k/m), the decay rate sigma = c/(2m), the Coulomb
// offset delta = F_d/k and the stick offset delta_s = F_s/k, which is what a position record can
// determine; m or k from calibration turns them back into forces.
//
// Solution: between velocity zeros the sign of x' is fixed, so the equation is linear with the
// equilibrium shifted to x_eq - s delta (s = sign x'). With y = x - x_eq + s delta and
// omega_d = sqrt(omega0^2 - sigma^2) (underdamped):
//     y(t)  = e^{-sigma t} (y0 cos omega_d t + (v0 + sigma y0)/omega_d sin omega_d t)
//     x'(t) = e^{-sigma t} (v0 cos omega_d t - (omega0^2 y0 + sigma v0)/omega_d sin omega_d t)
// so the next velocity zero is found in closed form (x' = R e^{-sigma t} cos(omega_d t + phi)).
// The record is therefore exact to round-off: no time step, and the events (reversal, stick) are
// located exactly. tests/friction_test checks it against a small-step RK4 and the classical
// Coulomb decrement 4 F_d / k per cycle.
#pragma once

#include <vector>

namespace tribex::friction_test {

struct OscillatorParams {
  double omega0 = 0.0;          // rad/s, sqrt(k/m)
  double sigma = 0.0;           // 1/s, c / (2 m); must be < omega0 (underdamped)
  double coulomb_offset = 0.0;  // m, F_d / k
  double stick_offset = 0.0;    // m, F_s / k; taken as coulomb_offset when smaller
  double x_eq = 0.0;            // m, position of the unloaded spring
};

struct OscillatorStart {
  double t0 = 0.0;  // s
  double x0 = 0.0;  // m
  double v0 = 0.0;  // m/s
};

/// Positions at `times` (non-decreasing, all >= start.t0). Returns false when the parameters are
/// outside the model's domain (omega0 <= 0, sigma < 0 or sigma >= omega0, negative offsets).
bool oscillator_positions(const OscillatorParams& p, const OscillatorStart& start,
                          const std::vector<double>& times, std::vector<double>& x_out);

/// Where the oscillator released at rest from x0 comes to a stop (the static test's post-slip
/// position), and the time that takes; at most `max_reversals` half cycles.
struct StopPoint {
  double x = 0.0;
  double time = 0.0;
  int reversals = 0;
};
StopPoint oscillator_stop(const OscillatorParams& p, double x0, int max_reversals = 100000);

}  // namespace tribex::friction_test
