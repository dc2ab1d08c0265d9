// SPDX-License-Identifier: MIT
#include "solver/stable_time_step.hpp"

#include <cmath>
#include <limits>

#include "materials/small_matrix.hpp"
#include "solver/hex8/geometry.hpp"

namespace tribex::solver {

StableStep compute_stable_time_step(const Model& model, const double* u, double* per_element) {
  StableStep out;
  out.dt = std::numeric_limits<double>::infinity();
  const auto& m = model.mesh;
  for (const auto& blk : model.blocks) {
    const double rho0 = materials::density_of(blk.material);
    const double xi = blk.linear_bulk_viscosity;
    const double damping_factor = std::sqrt(1.0 + xi * xi) - xi;
    for (int e = 0; e < blk.count; ++e) {
      const int global = blk.first_element + e;
      double B0[24];
      reference_gradient(blk, e, B0);
      double L = blk.length0[e];
      double H[9] = {};
      double J = 1.0;
      if (u) {
        // Current operator of the uniform-gradient element, B = cof(F) B0 (exact for an affine
        // deformation of the element, first order otherwise), V = J V0: no Gauss loop per element.
        for (int I = 0; I < 8; ++I) {
          const double* un = u + 3 * m.connectivity[8 * global + I];
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) H[3 * i + j] += un[i] * B0[8 * j + I];
        }
        for (double& h : H) h /= blk.volume0[e];
        const double F[9] = {1 + H[0], H[1], H[2], H[3], 1 + H[4], H[5], H[6], H[7], 1 + H[8]};
        double C[9];
        J = materials::cofactor3(F, C);
        if (!(J > 0.0)) {
          if (out.inverted_element < 0) out.inverted_element = global;
          continue;
        }
        double bb = 0.0;
        for (int I = 0; I < 8; ++I)
          for (int i = 0; i < 3; ++i) {
            const double b = C[3 * i] * B0[I] + C[3 * i + 1] * B0[8 + I] + C[3 * i + 2] * B0[16 + I];
            bb += b * b;
          }
        L = J * blk.volume0[e] / std::sqrt(2.0 * bb);
      }
      const double M = std::visit([&](const auto& mat) { return mat.wave_modulus(H); }, blk.material);
      // Mass scaling (docs/theory.md 1.4.1): the element's density is s_e rho0, so dt_e grows by sqrt(s_e).
      const double rho = (blk.mass_scale.empty() ? rho0 : rho0 * blk.mass_scale[e]) / J;
      const double dt = L / std::sqrt(M / rho) * damping_factor;
      if (per_element) per_element[global] = dt;
      if (dt < out.dt) {
        out.dt = dt;
        out.controlling_element = global;
      }
    }
  }
  return out;
}

}  // namespace tribex::solver
