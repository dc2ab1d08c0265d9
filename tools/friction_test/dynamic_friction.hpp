// SPDX-License-Identifier: MIT
// Dynamic friction from a post-slip position record (report Section 2.1.6, Figs. 2.10-2.11).
//
// The record (sampled at ~50 points per cycle) is fitted with the oscillator of oscillator.hpp,
// m x'' + c x' + k (x - x_eq) = -F_d sign(x'), by Levenberg-Marquardt over the parameters a
// position record determines: omega0, the decay rate sigma = c/(2m), the Coulomb offset
// delta = F_d / k, x_eq and the state (x0, v0) at the first sample. Coulomb friction shows as a
// linear decrement of the swing (4 delta per cycle), air damping as a geometric one, so the two
// are separable. Forces follow from the calibration: with the stiffness k given,
//     F_d = k delta,  c = 2 k sigma / omega0^2,  m = k / omega0^2;
// with the mass m given instead, k = m omega0^2, F_d = m omega0^2 delta, c = 2 m sigma.
// The calibration's relative uncertainty is added in quadrature to the fit's.
//
// Several records at different normal loads give the load line of Fig. 2.11,
//     F_d = mu_d F_N + mu_d F_adh,
// whose positive intercept at F_N = 0 is friction under zero (and tensile) applied load.
#pragma once

#include <string>
#include <vector>

#include "tools/common/least_squares.hpp"
#include "tools/friction_test/oscillator.hpp"
#include "tools/friction_test/static_friction.hpp"

namespace tribex::friction_test {

/// The calibration that turns offsets into forces: exactly one of stiffness or mass is > 0.
struct Calibration {
  double stiffness = 0.0, stiffness_sigma = 0.0;  // N/m
  double mass = 0.0, mass_sigma = 0.0;            // kg
};

struct DynamicFit {
  OscillatorParams oscillator;  // fitted
  OscillatorStart start;        // fitted
  double omega0_sigma = 0.0, sigma_sigma = 0.0, coulomb_offset_sigma = 0.0, x_eq_sigma = 0.0;
  double stiffness = 0.0, stiffness_sigma = 0.0;          // N/m
  double mass = 0.0, mass_sigma = 0.0;                    // kg
  double friction_force = 0.0, friction_force_sigma = 0.0;  // N, F_d
  double damping = 0.0, damping_sigma = 0.0;              // N s/m, c
  double quality = 0.0;                                   // omega0 / (2 sigma)
  double rms_residual = 0.0;                              // m
  std::size_t samples = 0;
  bool ends_at_rest = false;  // the record ends stuck (static friction held it)
  tools::FitResult fit;  // parameters (omega0, sigma, delta, x_eq, x0, v0)
  std::vector<double> model;  // fitted positions at the record's times
};

/// Throws tools::BadInput (naming `what`) when the record has too few samples or does not
/// oscillate, and std::runtime_error if the fit is degenerate.
DynamicFit fit_dynamic(const std::vector<double>& t, const std::vector<double>& x, const Calibration& cal,
                       const std::string& what);

/// Straight line F_d(F_N) through at least 3 records. With `friction_force_sigma` (one per
/// record) the parameter uncertainties are the larger of the scatter-based ones and those
/// propagated from the records' own 1-sigma errors, (A^T W A)^-1 with W = diag(1/sigma_i^2):
/// a handful of records gives too few degrees of freedom to trust the scatter alone.
FrictionLine fit_load_line(const std::vector<double>& normal_force, const std::vector<double>& friction_force,
                       const std::vector<double>& friction_force_sigma = {});

}  // namespace tribex::friction_test
