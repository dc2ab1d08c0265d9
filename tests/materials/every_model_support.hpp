// SPDX-License-Identifier: MIT
// What tests/materials/every_model_test.cpp and its lane-width files (every_model_avx2.cpp,
// every_model_avx512.cpp) share: one instance of every model of the list from its declared keys
// alone, the material points they run, and one update of those points at a lane width T.
// Internal linkage throughout (the lane-width files are built with -mavx2 / -mavx512f: nothing of
// theirs may be picked by the linker for the baseline code).
#pragma once

#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "inputs/units.hpp"
#include "materials/material.hpp"

namespace tribex::materials::every_model {
namespace {

constexpr double youngs = 100e9, poisson = 0.3, density = 2000.0;  // Pa, -, kg/m^3
constexpr int max_lanes = 8, max_state = 16;

/// The values a model gets from its declared keys alone: its declared defaults (parsed as the deck
/// builder parses them), and for a required key 1 % of E when it is a stress ("Pa", a yield stress
/// then yields at about 1 % strain, above the elastic points below) or 1 (its SI unit) otherwise,
/// above the key's lower bound.
inline KeyValues values_from_declarations(std::span<const KeyDecl> keys) {
  KeyValues v;
  for (const KeyDecl& k : keys) {
    if (!k.default_text.empty()) {
      std::string why;
      const auto q = inputs::parse_quantity(k.default_text, &why);
      v.numbers[std::string(k.key)] = q ? q->value : -1e300;  // unparsable: caught by the test
    } else if (k.required) {
      v.numbers[std::string(k.key)] = (k.unit == "Pa" ? 0.01 * youngs : 1.0) + (k.lower_bound > 0 ? k.lower_bound : 0.0);
    }
  }
  return v;
}

template <class M>
M make_model() {
  return M::make(lame_lambda(youngs, poisson), lame_mu(youngs, poisson), density, values_from_declarations(M::keys));
}

/// A displacement gradient of size `amplitude` in a fixed direction with every component nonzero.
inline std::array<double, 9> gradient(double amplitude, int variant = 0) {
  static constexpr double pattern[3][9] = {{0.3, -0.7, 0.2, 0.5, -0.1, 0.4, -0.6, 0.8, 0.1},
                                           {-0.5, 0.2, 0.6, -0.3, 0.9, -0.2, 0.1, -0.4, -0.7},
                                           {0.8, 0.1, -0.3, 0.2, -0.6, 0.5, 0.4, -0.2, 0.3}};
  std::array<double, 9> H;
  for (int k = 0; k < 9; ++k) H[k] = amplitude * pattern[variant % 3][k];
  return H;
}

/// Two updates (to H/2, then to H) of `lanes` points, lane l at gradient(lane_amplitudes[l], l):
/// every stress, energy, dissipation and state value, [group of lane_count<T>][step][lane][value],
/// into `out` (values_per_run<M>(lanes) doubles; a plain array: no std::vector code is made in the
/// lane-width files, which the linker could then pick for the baseline code).
inline constexpr double lane_amplitudes[max_lanes] = {1e-3, 0.05, 0.2, 0.0, 0.3, 2e-2, 0.1, 5e-3};
template <class M>
constexpr int values_per_point() { return 9 + 2 + M::state_size; }
template <class M>
constexpr int values_per_run(int lanes) { return lanes * 2 * values_per_point<M>(); }

/// The points at width T (T = double: one point at a time).
template <class T, class M>
void run_at_width(const M& m, int lanes, double* out) {
  static_assert(M::state_size <= max_state);
  for (int first = 0; first < lanes; first += lane_count<T>) {
    T state[max_state > 0 ? max_state : 1] = {};
    for (double fraction : {0.5, 1.0}) {
      T H[9], S[9], dissipated{};
      for (int k = 0; k < 9; ++k)
        H[k] = from_lanes<T>([&](int l) { return fraction * gradient(lane_amplitudes[first + l], first + l)[k]; });
      const T W = point_stress(m, H, state, 1e-15, S, dissipated);
      for (int l = 0; l < lane_count<T>; ++l) {
        for (int k = 0; k < 9; ++k) *out++ = lane(S[k], l);
        *out++ = lane(W, l);
        *out++ = lane(dissipated, l);
        for (int k = 0; k < M::state_size; ++k) *out++ = lane(state[k], l);
      }
    }
  }
}

/// run_at_width<T> for whichever model `m` holds; true (for the wider widths' files, every_model_lanes.hpp).
template <class T>
bool run_material_at_width(const Material& m, int lanes, double* out) {
  std::visit([&](const auto& model) { run_at_width<T>(model, lanes, out); }, m);
  return true;
}

/// The lane runs in the order the lone points give them (run_at_width groups them by register).
inline std::vector<double> by_point(const std::vector<double>& values, int lanes, int width, int per_point) {
  std::vector<double> out(values.size());
  const int steps = 2;
  for (int first = 0; first < lanes; first += width)
    for (int step = 0; step < steps; ++step)
      for (int l = 0; l < width; ++l) {
        const int from = ((first * steps) + step * width + l) * per_point;
        const int to = ((first + l) * steps + step) * per_point;
        std::memcpy(&out[static_cast<std::size_t>(to)], &values[static_cast<std::size_t>(from)],
                    sizeof(double) * static_cast<std::size_t>(per_point));
      }
  return out;
}

}  // namespace
}  // namespace tribex::materials::every_model
