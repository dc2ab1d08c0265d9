// SPDX-License-Identifier: MIT
#include "solver/stable_time_step.hpp"

#include <cmath>
#include <limits>

#include "solver/hex8/element_stable_step.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {

StableStep compute_stable_time_step(const Model& model, const double* u, double* per_element) {
  hex8::StableStepMin min;
  const auto& m = model.mesh;
  for (const auto& blk : model.blocks) {
    const double factor = hex8::bulk_viscosity_step_factor(blk);
    std::visit(
        [&](const auto& mat) {
          for (int e = 0; e < blk.count; ++e) {
            const int global = blk.first_element + e;
            double B0[24];
            reference_gradient(blk, e, B0);
            double H[9] = {};
            if (u) {
              // The element's mean gradient, summed as the force kernels sum it (hex8/element_stable_step.hpp).
              const double inv_v0 = 1.0 / blk.volume0[e];
              for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                  double sum = 0.0;
                  for (int I = 0; I < 8; ++I) sum += u[3 * m.connectivity[8 * global + I] + i] * B0[8 * j + I];
                  H[3 * i + j] = sum * inv_v0;
                }
            }
            const double dt = hex8::element_stable_step<double>(mat, blk, e, u ? H : nullptr, B0, factor);
            if (per_element) per_element[global] = dt;
            min.add(dt, global);
          }
        },
        blk.material);
  }
  return {min.dt, min.controlling_element, min.inverted_element};
}

StableStep whole_model_stable_time_step(const Model& model, double* per_element) {
  StableStep step = compute_stable_time_step(model, nullptr, per_element);
  if (step.controlling_element >= 0) step.controlling_element = model.domain.global_element[step.controlling_element];
  if (step.inverted_element >= 0) step.inverted_element = model.domain.global_element[step.inverted_element];
  if (!model.domain.serial()) {
    if (step.controlling_element < 0) step.controlling_element = model.domain.global_element_count;  // no elements here
    step.dt = parallel::min_location(step.dt, step.controlling_element);
  }
  return step;
}

}  // namespace tribex::solver
