// SPDX-License-Identifier: MIT
// Compressible neo-Hookean hyperelasticity (docs/theory.md section 3.2c), objective at any rotation:
//   W = (mu/2)(I1 - 3) - mu ln J + (lambda/2)(ln J)^2,   I1 = tr(F^T F),  J = det F     (J/m^3)
//   P = mu (F - F^{-T}) + lambda ln J F^{-T}              first Piola-Kirchhoff stress (Pa)
//   sigma = (1/J) [mu (B - I) + lambda ln J I],  B = F F^T  Cauchy stress (Pa)
// Reduces to linear elasticity with the same (lambda, mu) at small strain.
#pragma once

#include <array>
#include <string_view>

#include "materials/parameter.hpp"

#include <cmath>

#include "materials/small_matrix.hpp"
#include "materials/lanes.hpp"

namespace tribex::materials {

struct NeoHookean : Hyperelastic {
  static constexpr std::string_view deck_name = "neo_hookean";
  static constexpr std::string_view alias = "neohookean";
  static constexpr bool finite_strain = true;  // S is the first Piola-Kirchhoff stress, objective

  double lambda = 0.0;
  double mu = 0.0;
  double density = 0.0;

  static NeoHookean make(double lambda_, double mu_, double density_, const KeyValues& /*values*/) {
    return {{}, lambda_, mu_, density_};
  }

  /// First Piola-Kirchhoff stress from the displacement gradient H = F - I (row-major 3x3);
  /// f_iI = P_iJ B0_JI. Returns W; where J <= 0 (inverted element) ln J is NaN or -inf and W is
  /// NaN or +inf, not finite: the caller reports the element. No branch, so that T = double2
  /// (two elements at once, lanes.hpp) runs the same code.
  template <class T>
  T force_stress(const T H[9], T P[9]) const {
    const T F[9] = {1.0 + H[0], H[1], H[2], H[3], 1.0 + H[4], H[5], H[6], H[7], 1.0 + H[8]};
    // cof(F) = J F^{-T}
    T C[9];
    const T J = cofactor3(F, C);
    const T lnJ = lane_log(J);
    const T a = (lambda * lnJ - mu) / J;  // coefficient of F^{-T} = cof/J
    T I1{};
    for (int k = 0; k < 9; ++k) {
      P[k] = mu * F[k] + a * C[k];
      I1 += F[k] * F[k];
    }
    return 0.5 * mu * (I1 - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
  }

  /// Cauchy stress (Voigt xx yy zz xy yz zx) from H, for output.
  void cauchy_stress(const double H[9], double voigt[6]) const {
    const double F[9] = {1.0 + H[0], H[1], H[2], H[3], 1.0 + H[4], H[5], H[6], H[7], 1.0 + H[8]};
    const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                     F[2] * (F[3] * F[7] - F[4] * F[6]);
    auto b = [&](int i, int j) { return F[3 * i] * F[3 * j] + F[3 * i + 1] * F[3 * j + 1] + F[3 * i + 2] * F[3 * j + 2]; };
    const double p = lambda * std::log(J);
    voigt[0] = (mu * (b(0, 0) - 1.0) + p) / J;
    voigt[1] = (mu * (b(1, 1) - 1.0) + p) / J;
    voigt[2] = (mu * (b(2, 2) - 1.0) + p) / J;
    voigt[3] = mu * b(0, 1) / J;
    voigt[4] = mu * b(1, 2) / J;
    voigt[5] = mu * b(2, 0) / J;
  }

  /// Dilatational modulus linearised at J (docs/theory.md 1.4): lambda' = lambda/J,
  /// mu' = (mu - lambda ln J)/J, M = lambda' + 2 mu'.
  double wave_modulus(const double* H) const {
    if (!H) return lambda + 2.0 * mu;
    const double F[9] = {1.0 + H[0], H[1], H[2], H[3], 1.0 + H[4], H[5], H[6], H[7], 1.0 + H[8]};
    const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                     F[2] * (F[3] * F[7] - F[4] * F[6]);
    if (!(J > 0.0)) return lambda + 2.0 * mu;
    return (lambda + 2.0 * mu - 2.0 * lambda * std::log(J)) / J;
  }
};

}  // namespace tribex::materials
