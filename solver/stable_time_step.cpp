// SPDX-License-Identifier: MIT
#include "solver/stable_time_step.hpp"

#include <cmath>
#include <limits>

#include "solver/hex8/geometry.hpp"

namespace tribex::solver {

StableStep compute_stable_time_step(const Model& model, const double* u) {
  StableStep out;
  out.dt = std::numeric_limits<double>::infinity();
  const auto& m = model.mesh;
  for (const auto& blk : model.blocks) {
    const double rho0 = materials::density_of(blk.material);
    const double xi = blk.linear_bulk_viscosity;
    const double damping_factor = std::sqrt(1.0 + xi * xi) - xi;
    for (int e = 0; e < blk.count; ++e) {
      const int global = blk.first_element + e;
      double X[24];
      for (int I = 0; I < 8; ++I) {
        const int n = m.connectivity[8 * global + I];
        for (int i = 0; i < 3; ++i) X[3 * I + i] = m.coordinates[3 * n + i] + (u ? u[3 * n + i] : 0.0);
      }
      double B[24];
      const double V = hex8::gradient_operator(X, B);
      if (!(V > 0.0)) {
        if (out.inverted_element < 0) out.inverted_element = global;
        continue;
      }
      // Tangent modulus at the element's mean deformation H = (1/V0) u_iI B0_jI.
      double H[9] = {};
      if (u) {
        const double* B0 = &blk.B0[24 * e];
        for (int I = 0; I < 8; ++I) {
          const int n = m.connectivity[8 * global + I];
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) H[3 * i + j] += u[3 * n + i] * B0[8 * j + I] / blk.volume0[e];
        }
      }
      const double M = std::visit([&](const auto& mat) { return mat.wave_modulus(H); }, blk.material);
      const double rho = rho0 * blk.volume0[e] / V;
      const double dt = hex8::characteristic_length(B, V) / std::sqrt(M / rho) * damping_factor;
      if (dt < out.dt) {
        out.dt = dt;
        out.controlling_element = global;
      }
    }
  }
  return out;
}

}  // namespace tribex::solver
