// SPDX-License-Identifier: MIT
// J2 (von Mises) plasticity with linear isotropic hardening, small strain, by radial return
// (docs/theory.md section 3.3; Simo & Hughes, Computational Inelasticity, 1998, Box 3.1):
//   eps = sym(H),  eps_e = eps - eps_p,  sigma = kappa tr(eps) I + 2 mu dev(eps_e)         (Pa)
//   f = |s| - sqrt(2/3) (Y + K alpha),  s = dev(sigma)                       (yield function, Pa)
//   trial: s* = 2 mu dev(eps - eps_p^n);  dgamma = <f(s*, alpha^n)> / (2 mu + (2/3) K)
//   n = s*/|s*|;  eps_p^{n+1} = eps_p^n + dgamma n;  alpha^{n+1} = alpha^n + sqrt(2/3) dgamma
//   s^{n+1} = s* - 2 mu dgamma n
// Y: initial uniaxial yield stress, K: linear isotropic hardening modulus (the slope of the
// uniaxial stress against the plastic strain, Pa), alpha: equivalent plastic strain.
// Returned energy: the stored elastic energy W_e = (1/2) kappa tr(eps)^2 + mu |dev(eps_e)|^2. The
// plastic work of the update goes to `dissipated` (J/m^3; the energy balance counts it as dissipated,
// hardening included, solver/energy.hpp). On the yield surface sigma : deps_p = |s| dgamma =
// sigma_y(alpha) dalpha, integrated exactly over the step for linear hardening:
//   dD = dalpha (Y + K (alpha^n + alpha^{n+1})/2) = dgamma (sqrt(2/3)(Y + K alpha^n) + K dgamma/3),
// the trapezoidal rule of the loop's external work (solver/integrators/central_difference.cpp), so
// the balance closes as in an elastic run. (Backward Euler, |s^{n+1}| dgamma, would overstate the
// work by K dalpha/2 per unit alpha: 2.6e-4 of the balance in the uniaxial verification.)
// Geometrically linear like LinearElastic: use where rotations are small. Rate independent (dt
// unused). No branch on the values, so that T = double2 runs two elements in one register
// (lanes.hpp); std::sqrt is correctly rounded lane by lane, so a pair is bitwise the lone pair.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "materials/lanes.hpp"
#include "materials/parameter.hpp"

namespace tribex::materials {

struct J2Plasticity {
  static constexpr std::string_view deck_name = "j2_plasticity";
  static constexpr std::string_view alias = "j2";
  static constexpr bool finite_strain = false;  // small strain: S is the Cauchy stress
  static constexpr std::array<KeyDecl, 2> keys{{
      {"yield stress", "Pa", 0.0, true, true, "Y, initial uniaxial yield stress"},
      {"hardening modulus", "Pa", 0.0, false, false, "K, slope of uniaxial stress against plastic strain", "0"},
  }};
  /// Per material point: eps_p (xx yy zz xy yz zx, tensor components) and alpha.
  static constexpr int state_size = 7;
  static constexpr int equivalent_plastic_strain_index = 6;  // alpha: the element field of that name
  static constexpr bool dissipates = true;

  double lambda = 0.0;
  double mu = 0.0;
  double density = 0.0;
  double yield_stress = 0.0;       // Y, Pa
  double hardening_modulus = 0.0;  // K, Pa

  static J2Plasticity make(double lambda_, double mu_, double density_, const KeyValues& values) {
    return {lambda_, mu_, density_, values.at("yield stress"), values.at("hardening modulus")};
  }

  /// Stress S (Cauchy, symmetric, row-major 3x3) at the gradient H and state n -> n+1 in place;
  /// returns W_e, sets `dissipated` to the plastic work density of this update (J/m^3).
  template <class T>
  T force_stress(const T H[9], T* state, double /*dt*/, T S[9], T& dissipated) const {
    const T tr = H[0] + H[4] + H[8];
    const T third_tr = tr * (1.0 / 3.0);
    // Deviatoric elastic trial strain e = dev(eps) - eps_p (eps_p is deviatoric: tr eps_p = 0).
    T e[6] = {H[0] - third_tr - state[0],
              H[4] - third_tr - state[1],
              H[8] - third_tr - state[2],
              0.5 * (H[1] + H[3]) - state[3],
              0.5 * (H[5] + H[7]) - state[4],
              0.5 * (H[2] + H[6]) - state[5]};
    const T norm_e = lane_sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] +
                               2.0 * (e[3] * e[3] + e[4] * e[4] + e[5] * e[5]));
    const T norm_s_trial = 2.0 * mu * norm_e;
    const T yield = std::sqrt(2.0 / 3.0) * (yield_stress + hardening_modulus * state[6]);
    const T dgamma = positive_part(norm_s_trial - yield) / (2.0 * mu + (2.0 / 3.0) * hardening_modulus);
    // deps_p = dgamma n = c e,  c = dgamma/|e| (0 where there is no flow, e = 0 included).
    const T c = dgamma / lane_max(norm_e, 1e-300);
    for (int k = 0; k < 6; ++k) {
      const T de_p = c * e[k];
      state[k] += de_p;
      e[k] -= de_p;  // now the deviatoric elastic strain at n+1
    }
    state[6] += std::sqrt(2.0 / 3.0) * dgamma;
    const T p = (lambda + 2.0 / 3.0 * mu) * tr;
    S[0] = p + 2.0 * mu * e[0];
    S[4] = p + 2.0 * mu * e[1];
    S[8] = p + 2.0 * mu * e[2];
    S[1] = S[3] = 2.0 * mu * e[3];
    S[5] = S[7] = 2.0 * mu * e[4];
    S[2] = S[6] = 2.0 * mu * e[5];
    dissipated = (yield + (1.0 / 3.0) * hardening_modulus * dgamma) * dgamma;
    const T ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + 2.0 * (e[3] * e[3] + e[4] * e[4] + e[5] * e[5]);
    return 0.5 * (lambda + 2.0 / 3.0 * mu) * tr * tr + mu * ee;
  }

  /// Cauchy stress (Voigt xx yy zz xy yz zx) at H with the state already updated to this H.
  void cauchy_stress(const double H[9], const double* state, double voigt[6]) const {
    const double tr = H[0] + H[4] + H[8];
    const double p = (lambda + 2.0 / 3.0 * mu) * tr;
    voigt[0] = p + 2.0 * mu * (H[0] - tr / 3.0 - state[0]);
    voigt[1] = p + 2.0 * mu * (H[4] - tr / 3.0 - state[1]);
    voigt[2] = p + 2.0 * mu * (H[8] - tr / 3.0 - state[2]);
    voigt[3] = 2.0 * mu * (0.5 * (H[1] + H[3]) - state[3]);
    voigt[4] = 2.0 * mu * (0.5 * (H[5] + H[7]) - state[4]);
    voigt[5] = 2.0 * mu * (0.5 * (H[2] + H[6]) - state[5]);
  }

  /// The elastic P-wave modulus bounds the tangent one: the stable step of the elastic material.
  double wave_modulus(const double* /*H*/) const { return lambda + 2.0 * mu; }
};

}  // namespace tribex::materials
