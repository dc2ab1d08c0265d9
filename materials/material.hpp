// SPDX-License-Identifier: MIT
// The material of an element block: a std::variant of small value types. Element kernels are
// templates over the concrete type and the variant is visited once per block per step, so there
// is no virtual or variant dispatch per element or quadrature point (docs/conventions.md A.4.3).
//
// Every model provides:
//   T force_stress(const T H[9], T S[9]) const;  // S with f_iI = S_iJ B0_JI; returns W (J/m^3);
//                                                 // T = double or double2 (lanes.hpp)
//   void cauchy_stress(const double H[9], double voigt[6]) const;
//   double wave_modulus(const double* H) const;                  // M = lambda + 2 mu (tangent), Pa
//   double density;                                               // kg/m^3
#pragma once

#include <variant>

#include "materials/linear_elastic.hpp"
#include "materials/neo_hookean.hpp"

namespace tribex::materials {

using Material = std::variant<LinearElastic, NeoHookean>;

/// Lame constants from Young's modulus and Poisson's ratio.
inline double lame_lambda(double E, double nu) { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
inline double lame_mu(double E, double nu) { return E / (2.0 * (1.0 + nu)); }

inline double density_of(const Material& m) {
  return std::visit([](const auto& x) { return x.density; }, m);
}
inline double shear_modulus_of(const Material& m) {
  return std::visit([](const auto& x) { return x.mu; }, m);
}
inline double wave_modulus_of(const Material& m) {
  return std::visit([](const auto& x) { return x.wave_modulus(nullptr); }, m);
}

}  // namespace tribex::materials
