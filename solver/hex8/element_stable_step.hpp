// SPDX-License-Identifier: MIT
// One element's stable step (docs/theory.md 1.4, 1.4.1), shared by compute_stable_time_step and
// the force kernels that fold the estimate into their pass (same arithmetic, so the same bits):
//   dt_e = L_e / c_d (sqrt(1 + xi^2) - xi),  L_e = J V0 / sqrt(2 B.B),  B = cof(F) B0,
//   c_d = sqrt(M(H) / rho),  rho = s_e rho0 / J   (s_e: the mass-scaling factor, 1 unscaled)
// H is the element's mean displacement gradient, H_ij = (u_iI B0_jI) * (1 / V0), summed over I in
// node order. Reference configuration (no H): L_e = length0. Elements 1, 2 or 4 at a time (T lanes),
// the same IEEE operations in every lane.
#pragma once

#include <cmath>

#include "materials/lanes.hpp"
#include "materials/small_matrix.hpp"
#include "solver/element_block.hpp"

namespace tribex::solver::hex8 {

/// sqrt(1 + xi^2) - xi for the block's linear bulk viscosity xi = b1.
inline double bulk_viscosity_step_factor(const ElementBlock& blk) {
  const double xi = blk.linear_bulk_viscosity;
  return std::sqrt(1.0 + xi * xi) - xi;
}

/// dt_e (s) of elements e .. e + lane_count<T> - 1 at their mean gradients H (T lanes; nullptr:
/// the reference configuration); a non-positive J gives 0 (the caller names the element as inverted).
template <class T, class Material>
inline T element_stable_step(const Material& mat, const ElementBlock& blk, int e, const T* H, const T B0[24],
                             double step_factor) {
  T L = materials::load_lanes<T>(&blk.length0[e]);
  T J = T{} + 1.0;
  T M;
  if (!H) {
    M = T{} + mat.wave_modulus(nullptr);
  } else {
    const T F[9] = {1.0 + H[0], H[1], H[2], H[3], 1.0 + H[4], H[5], H[6], H[7], 1.0 + H[8]};
    T C[9];
    J = materials::cofactor3(F, C);
    T bb{};
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) {
        const T b = C[3 * i] * B0[I] + C[3 * i + 1] * B0[8 + I] + C[3 * i + 2] * B0[16 + I];
        bb += b * b;
      }
    L = J * materials::load_lanes<T>(&blk.volume0[e]) / materials::lane_sqrt(2.0 * bb);
    M = materials::from_lanes<T>([&](int l) {
      double Hl[9];
      for (int k = 0; k < 9; ++k) Hl[k] = materials::lane(H[k], l);
      return mat.wave_modulus(Hl);
    });
  }
  const double rho0 = mat.density;
  const T rho = (blk.mass_scale.empty() ? T{} + rho0 : rho0 * materials::load_lanes<T>(&blk.mass_scale[e])) / J;
  const T dt = L / materials::lane_sqrt(M / rho) * step_factor;
  return materials::from_lanes<T>([&](int l) { return materials::lane(J, l) > 0.0 ? materials::lane(dt, l) : 0.0; });
}

/// The running minimum of a pass: the smallest dt_e and its element (the first in element order
/// on ties), and the first inverted element.
struct StableStepMin {
  double dt = INFINITY;
  int controlling_element = -1;  // global element index
  int inverted_element = -1;     // global element index

  void add(double dt_e, int global) {
    if (!(dt_e > 0.0)) {
      if (inverted_element < 0) inverted_element = global;
      return;
    }
    if (dt_e < dt) {
      dt = dt_e;
      controlling_element = global;
    }
  }
};

/// The stable steps of elements e .. e + lane_count<T> - 1 from a kernel's registers (H [9] and
/// B0 [24], T lanes), added to the minimum lane by lane in element order.
template <class T, class Material>
inline void add_stable_steps(const Material& mat, const ElementBlock& blk, int e, const T H[9], const T B0[24],
                             StableStepMin& min) {
  const T dt = element_stable_step(mat, blk, e, H, B0, bulk_viscosity_step_factor(blk));
  for (int l = 0; l < materials::lane_count<T>; ++l) min.add(materials::lane(dt, l), blk.first_element + e + l);
}

}  // namespace tribex::solver::hex8
