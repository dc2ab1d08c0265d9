// SPDX-License-Identifier: MIT
// Synthetic friction-test records from the models with known parameters and seeded Gaussian
// position noise (standard deviation `noise`: the report's metrology is +-10 nm for sub-pixel
// image analysis and +-1 nm for the Moire gauge, Section 2.1.4). Used by the tests to recover
// the parameters, and by `tribex friction-test synth` for examples.
#pragma once

#include <cstdint>

#include "tools/common/csv_record.hpp"
#include "tools/friction_test/static_friction.hpp"

namespace tribex::friction_test {

struct OscillatorSetup {
  double mass = 2.25e-9;         // kg (report: 2.25 +- 0.15, see calibration.hpp on ng vs ug)
  double stiffness = 0.38;       // N/m (report: 0.38 +- 0.03 N/m)
  double damping = 0.0;          // N s/m, c
  double friction_force = 0.0;   // N, F_d
  double static_force = 0.0;     // N, F_s (stick threshold; F_d when smaller)
  double x_eq = 0.0;             // m
  double x_release = 5e-6;       // m, released at rest here (t = 0)
  double samples_per_cycle = 50;
  double cycles = 12;
  double noise = 10e-9;          // m
  std::uint64_t seed = 1;
};
/// Columns time[s], position[nm]; the ringdown when friction_force is 0.
tools::CsvRecord synth_oscillator(const OscillatorSetup& s, const std::string& name = "synthetic");

struct StaticSetup {
  double stiffness = 4.5;          // N/m (report: Load Spring A, Fig. 2.6)
  double mu_s = 0.31, mu_d = 0.28;
  double adhesion_force = 0.0;     // N (report: 1 nN/um^2 times the foot area)
  ClampLoad clamp{2.4e-7, 2e-6};   // 0.24 mm^2 at 2 um: 10.6 mN at 200 V as in the report
  double mass = 2.25e-9, damping = 2e-7;  // kg, N s/m: the post-slip oscillator
  double x_zero = 0.0;             // m, spring zero
  double x_start = 40e-6;          // m, walked out this far
  double volts_start = 100, volts_step = 0.1;  // ramped down to 0
  double noise = 10e-9;            // m
  std::uint64_t seed = 1;
};
/// Columns voltage[V], position[nm]: holds while mu_s (F_N + F_adh) >= k |x - x_zero|, else slips
/// and stops where the Coulomb oscillator (mu_d, damping) comes to rest.
tools::CsvRecord synth_static(const StaticSetup& s, const std::string& name = "synthetic");

}  // namespace tribex::friction_test
