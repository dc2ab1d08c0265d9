// SPDX-License-Identifier: MIT
// Isotropic linear elasticity, small strain (docs/theory.md section 3.1):
//   eps = sym(H),  H = du/dX (displacement gradient, 3x3 row-major)
//   sigma = lambda tr(eps) I + 2 mu eps                       (Pa)
//   W = (1/2) sigma : eps                                      (J/m^3)
// Geometrically linear: stresses are not rotated, so use it where rotations are small (the
// indentation and sliding problems tribex is for); neo_hookean is the objective finite-strain model.
// Parameters: lambda, mu (Pa), density (kg/m^3).
#pragma once

#include <array>
#include <string_view>

#include "materials/parameter.hpp"

namespace tribex::materials {

struct LinearElastic : Hyperelastic {
  static constexpr std::string_view deck_name = "elastic";
  static constexpr std::string_view alias = "";
  static constexpr bool finite_strain = false;  // S is the Cauchy stress of eps = sym(H)

  double lambda = 0.0;
  double mu = 0.0;
  double density = 0.0;

  static LinearElastic make(double lambda_, double mu_, double density_, const KeyValues& /*values*/) {
    return {{}, lambda_, mu_, density_};
  }

  /// Stress from the displacement gradient H (row-major 3x3): the stress that multiplies the
  /// reference gradient operator in the internal force, f_iI = S_ij B0_jI. For small strain this is
  /// the Cauchy stress sigma (symmetric). Returns the strain-energy density W. T = double, or
  /// double2 for two elements at once (lanes.hpp).
  template <class T>
  T force_stress(const T H[9], T S[9]) const {
    const T tr = H[0] + H[4] + H[8];
    const T e01 = 0.5 * (H[1] + H[3]), e02 = 0.5 * (H[2] + H[6]), e12 = 0.5 * (H[5] + H[7]);
    S[0] = lambda * tr + 2.0 * mu * H[0];
    S[4] = lambda * tr + 2.0 * mu * H[4];
    S[8] = lambda * tr + 2.0 * mu * H[8];
    S[1] = S[3] = 2.0 * mu * e01;
    S[2] = S[6] = 2.0 * mu * e02;
    S[5] = S[7] = 2.0 * mu * e12;
    // W = (1/2) sigma:eps, off-diagonal pairs counted twice.
    return 0.5 * (S[0] * H[0] + S[4] * H[4] + S[8] * H[8]) + S[1] * e01 + S[2] * e02 + S[5] * e12;
  }

  /// Cauchy stress (Voigt xx yy zz xy yz zx) from H, for output.
  void cauchy_stress(const double H[9], double voigt[6]) const {
    double S[9];
    force_stress(H, S);
    voigt[0] = S[0]; voigt[1] = S[4]; voigt[2] = S[8];
    voigt[3] = S[1]; voigt[4] = S[5]; voigt[5] = S[2];
  }

  /// P-wave (dilatational) modulus M = lambda + 2 mu at the deformation H (constant here).
  double wave_modulus(const double* /*H*/) const { return lambda + 2.0 * mu; }
};

}  // namespace tribex::materials
