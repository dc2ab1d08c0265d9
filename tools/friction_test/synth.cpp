// SPDX-License-Identifier: MIT
#include "tools/friction_test/synth.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "tools/friction_test/oscillator.hpp"

namespace tribex::friction_test {

tools::CsvRecord synth_oscillator(const OscillatorSetup& s, const std::string& name) {
  OscillatorParams p;
  p.omega0 = std::sqrt(s.stiffness / s.mass);
  p.sigma = s.damping / (2 * s.mass);
  p.coulomb_offset = s.friction_force / s.stiffness;
  p.stick_offset = s.static_force / s.stiffness;
  p.x_eq = s.x_eq;
  const double dt = 2 * std::numbers::pi / p.omega0 / s.samples_per_cycle;
  const auto n = static_cast<std::size_t>(s.samples_per_cycle * s.cycles) + 1;
  std::vector<double> t(n), x;
  for (std::size_t i = 0; i < n; ++i) t[i] = dt * static_cast<double>(i);
  oscillator_positions(p, {0.0, s.x_release, 0.0}, t, x);
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> noise(0.0, s.noise);
  for (double& v : x) v += noise(rng);
  return tools::CsvRecord(name, {{"time", {t, "s"}}, {"position", {x, "nm"}}});
}

tools::CsvRecord synth_static(const StaticSetup& s, const std::string& name) {
  std::vector<double> volts, x;
  double pos = s.x_start;
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> noise(0.0, s.noise);
  ClampLoad clamp = s.clamp;
  const auto steps = static_cast<long>(std::llround(s.volts_start / s.volts_step));
  for (long i = 0; i <= steps; ++i) {
    const double v = s.volts_start - s.volts_step * static_cast<double>(i);
    const double load = clamp.normal_force(v) + s.adhesion_force;  // F_N + F_adh
    const double capacity = s.mu_s * load;
    if (s.stiffness * std::abs(pos - s.x_zero) > capacity) {
      OscillatorParams p;
      p.omega0 = std::sqrt(s.stiffness / s.mass);
      p.sigma = s.damping / (2 * s.mass);
      p.coulomb_offset = std::max(0.0, s.mu_d * load) / s.stiffness;
      p.stick_offset = std::max(0.0, capacity) / s.stiffness;
      p.x_eq = s.x_zero;
      pos = oscillator_stop(p, pos).x;
    }
    volts.push_back(v);
    x.push_back(pos + noise(rng));
  }
  return tools::CsvRecord(name, {{"voltage", {volts, "V"}}, {"position", {x, "nm"}}});
}

}  // namespace tribex::friction_test
