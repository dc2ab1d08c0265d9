// SPDX-License-Identifier: MIT
// The material of an element block: a std::variant of small value types, and the one list of
// them (`Material` below) from which the deck schema, the deck builder, `make_material`, the key
// reference and the labels are made. Element kernels are templates over the concrete type and the
// variant is visited once per block per step, so there is no virtual or variant dispatch per
// element or material point (docs/conventions.md A.4.3).
//
// Every model provides (README.md, "Adding a material"):
//   static constexpr std::string_view deck_name, alias ("" for none);
//   static constexpr std::array<KeyDecl, N> keys;   // its deck keys beyond E and nu (inputs/keys/key_decl.hpp)
//   static constexpr bool finite_strain;             // S is P (objective); false: small-strain Cauchy
//   static constexpr int state_size;                 // doubles per material point
//   static constexpr bool dissipates;                // returns plastic work
//   static M make(double lambda, double mu, double density, const KeyValues& values);  // values by key name
//   stateless (state_size == 0):
//     T force_stress(const T H[9], T S[9]) const;     // S with f_iI = S_iJ B0_JI; returns W (J/m^3)
//     void cauchy_stress(const double H[9], double voigt[6]) const;
//   stateful: the state of the point goes n -> n+1 in place, `dissipated` gets the work density
//   the update dissipates (J/m^3):
//     T force_stress(const T H[9], T* state, double dt, T S[9], T& dissipated) const;
//     void cauchy_stress(const double H[9], const double* state, double voigt[6]) const;
//   double wave_modulus(const double* H) const;   // P-wave modulus of the tangent at H, Pa; H may be
//                                                 // null (the reference value); the rule: README.md
//   double density, mu;                           // kg/m^3, Pa
// T = double, double2, double4 or double8 (lanes.hpp; the last two only in the AVX2 / AVX-512 files).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "materials/j2_plasticity.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/neo_hookean.hpp"

namespace tribex::materials {

/// Every material model; a new one is a header and one entry here.
using Material = std::variant<LinearElastic, NeoHookean, J2Plasticity>;

inline constexpr int model_count = static_cast<int>(std::variant_size_v<Material>);

/// f(std::type_identity<M>{}, index) for every model M of the list, in order.
template <class F>
void for_each_model(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(std::type_identity<std::variant_alternative_t<I, Material>>{}, static_cast<int>(I)), ...);
  }(std::make_index_sequence<std::variant_size_v<Material>>{});
}

/// Deck names of the models, in the list's order.
inline std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for_each_model([&](auto m, int) { names.emplace_back(decltype(m)::type::deck_name); });
  return names;
}
/// (alias, deck name) pairs of the models that have an alias.
inline std::vector<std::pair<std::string, std::string>> model_aliases() {
  std::vector<std::pair<std::string, std::string>> aliases;
  for_each_model([&](auto m, int) {
    using M = typename decltype(m)::type;
    if (!M::alias.empty()) aliases.emplace_back(M::alias, M::deck_name);
  });
  return aliases;
}
/// Index of the model with this deck name, or -1.
inline int model_index(std::string_view name) {
  int found = -1;
  for_each_model([&](auto m, int i) {
    if (decltype(m)::type::deck_name == name) found = i;
  });
  return found;
}
/// The deck keys of model `index` beyond the elastic constants.
inline std::span<const KeyDecl> model_keys(int index) {
  std::span<const KeyDecl> found;
  for_each_model([&](auto m, int i) {
    if (i == index) found = decltype(m)::type::keys;
  });
  return found;
}

/// Lame constants from Young's modulus and Poisson's ratio.
inline double lame_lambda(double E, double nu) { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
inline double lame_mu(double E, double nu) { return E / (2.0 * (1.0 + nu)); }

/// Model `index` from its elastic constants, density and the values of its own keys (model_keys, by
/// name, defaults filled in).
inline Material make_material(int index, double E, double nu, double density, const KeyValues& values) {
  Material made;
  for_each_model([&](auto m, int i) {
    if (i == index) made = decltype(m)::type::make(lame_lambda(E, nu), lame_mu(E, nu), density, values);
  });
  return made;
}

inline std::string_view model_name(const Material& m) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::deck_name; }, m);
}
inline double density_of(const Material& m) {
  return std::visit([](const auto& x) { return x.density; }, m);
}
inline double shear_modulus_of(const Material& m) {
  return std::visit([](const auto& x) { return x.mu; }, m);
}
inline double wave_modulus_of(const Material& m) {
  return std::visit([](const auto& x) { return x.wave_modulus(nullptr); }, m);
}
/// Doubles of state per material point.
inline int state_size_of(const Material& m) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::state_size; }, m);
}
inline bool dissipates(const Material& m) {
  return std::visit([](const auto& x) { return std::decay_t<decltype(x)>::dissipates; }, m);
}

/// One material point, n -> n+1: the one call the element kernels make, whatever the model.
template <class M, class T>
inline T point_stress(const M& m, const T H[9], T* state, double dt, T S[9], T& dissipated) {
  if constexpr (M::state_size == 0) {
    dissipated = T{};
    return m.force_stress(H, S);
  } else {
    return m.force_stress(H, state, dt, S, dissipated);
  }
}
/// Cauchy stress for output, with the point's state already at this H.
template <class M>
inline void point_cauchy_stress(const M& m, const double H[9], const double* state, double voigt[6]) {
  if constexpr (M::state_size == 0)
    m.cauchy_stress(H, voigt);
  else
    m.cauchy_stress(H, state, voigt);
}

}  // namespace tribex::materials
