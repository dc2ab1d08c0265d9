// SPDX-License-Identifier: MIT
#include "tools/pstd/stepping.hpp"

#include <string>

#include "tools/common/errors.hpp"

namespace tribex::pstd {

double restoring_force(const std::vector<double>& coefficients_uN_um, double x) {
  const double x_um = x * 1e6;
  double r = 0.0;
  for (auto c = coefficients_uN_um.rbegin(); c != coefficients_uN_um.rend(); ++c) r = r * x_um + *c;  // Horner
  return r * 1e-6;
}

Run simulate(const Model& model, const Drive& drive) {
  Run run;
  Gap gap(model);
  double force = drive.normal_force;
  double interference_guess = 1e-10;
  run.steps.reserve(drive.steps + 1);
  for (std::size_t k = 0; k <= drive.steps; ++k) {
    StepRecord rec;
    rec.position = model.dx * static_cast<double>(k);
    // Step 4 (or 0 at k = 0): re-establish the normal force at this position.
    gap.set_travel(k);
    double height = height_for_force(gap, force, 2.0 * interference_guess);
    ContactState state = gap.evaluate(height);
    rec.normal_force_arrival = state.force;
    if (k == 0) {
      run.initial_contacts = state.contacts;
      run.initial_area = state.area;
      run.initial_normal_force = state.force;
    }
    // Steps 1-3: capacity against restoring force; lift while the junctions can hold the device.
    rec.displacement = drive.start_displacement - rec.position;
    rec.restoring = restoring_force(drive.restoring_uN_per_um_pow, rec.displacement);
    const double tau = model.mechanics.shear_strength;
    if (rec.restoring <= tau * state.area) {
      if (!(rec.restoring > 0.0))
        throw tools::BadInput("tribex pstd: the restoring force is " + std::to_string(rec.restoring * 1e6) +
                              " uN <= 0 at x = " + std::to_string(rec.displacement * 1e6) +
                              " um, so the counterface can never move; give --restoring coefficients that "
                              "stay positive over the travel");
      height = height_for_area_below(gap, height, rec.restoring / tau);
      state = gap.evaluate(height);
      force = state.force;
      rec.lifted = true;
    }
    rec.normal_force = state.force;
    rec.capacity = tau * state.area;
    rec.area = state.area;
    rec.mean_half_width = state.mean_half_width;
    rec.max_interference = state.max_interference;
    rec.contacts = state.contacts;
    run.clamped_contacts += static_cast<std::size_t>(state.clamped);
    if (state.max_interference > 0.0) interference_guess = state.max_interference;
    run.steps.push_back(rec);
  }
  return run;
}

}  // namespace tribex::pstd
