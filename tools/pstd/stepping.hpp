// SPDX-License-Identifier: MIT
// The quasi-static stepping of the PSTD model, exactly in the order of the seed report (Section 2.1.9):
//   0. press the counterface in until the summed contact force equals the prescribed normal force W;
//   then at every position x (1 grid step = 1 nm in the report):
//   1. shear capacity C = tau* A (eq. 2.7) from the current true contact area A;
//   2. restoring force R(x) = polynomial in x (eq. 2.8: x in um, R in uN); x is the device's displacement from
//      its neutral position: it starts at x0 and decreases by one grid step per advance (the restoring force
//      drives the counterface back toward neutral, as in the nanotractor's static friction test);
//   3. if R <= C: displace the counterface upward (reducing W and A) until R > C; W keeps this reduced value;
//   4. advance one grid step and re-establish W by moving the counterface vertically; repeat from 1
//      until the requested travel is covered.
#pragma once

#include <cstddef>
#include <vector>

#include "tools/pstd/model.hpp"

namespace tribex::pstd {

struct Drive {
  double normal_force = 0.0;                     // initial prescribed normal force W, N
  std::vector<double> restoring_uN_per_um_pow;   // R(x) = sum_j c_j x^j, x in um, R in uN (eq. 2.8 form)
  std::size_t steps = 0;                         // number of grid steps to travel
  double start_displacement = 0.0;               // x0, m; R is evaluated at x = x0 - travel
};

/// R(x) in N for x in m, from the eq. (2.8)-style polynomial coefficients (uN, um).
double restoring_force(const std::vector<double>& coefficients_uN_um, double x);

/// The state at one position. "arrival": after the normal force was re-established there; "departure":
/// after any lift, i.e. the state in which the counterface advances to the next position.
struct StepRecord {
  double position = 0.0;               // travel, m
  double normal_force_arrival = 0.0;   // N
  double normal_force = 0.0;           // departure normal force, N
  double displacement = 0.0;           // x = x0 - position, m
  double restoring = 0.0;              // R(x), N
  double capacity = 0.0;               // departure shear capacity tau* A, N
  double area = 0.0;                   // departure true contact area, m^2
  double mean_half_width = 0.0;        // m
  double max_interference = 0.0;       // m
  int contacts = 0;                    // departure
  bool lifted = false;                 // R <= C on arrival, so the counterface was lifted here
};

struct Run {
  std::vector<StepRecord> steps;  // positions 0, dx, ..., steps*dx
  int initial_contacts = 0;       // after the press-in at x = 0, before any lift
  double initial_area = 0.0;      // m^2
  double initial_normal_force = 0.0;
  std::size_t clamped_contacts = 0;  // 2-D contact evaluations beyond the law's range (summed over steps)
};

/// Runs the stepping; throws tools::BadInput when R(x) <= 0 (the counterface could never move).
Run simulate(const Model& model, const Drive& drive);

}  // namespace tribex::pstd
