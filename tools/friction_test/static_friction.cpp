// SPDX-License-Identifier: MIT
#include "tools/friction_test/static_friction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tools/common/errors.hpp"

namespace tribex::friction_test {

double ClampLoad::normal_force(double volts) const {
  const double clamp = vacuum_permittivity * electrode_area * volts * volts / (2 * gap * gap);
  return clamp + mass * standard_gravity - kz * z;
}

std::vector<SlipEvent> detect_slips(const std::vector<double>& position, const std::vector<double>& normal_force,
                                    double stiffness, double x_zero, double min_jump) {
  std::vector<SlipEvent> events;
  for (std::size_t i = 0; i + 1 < position.size(); ++i) {
    const double jump = position[i + 1] - position[i];
    const double from_zero = position[i] - x_zero;
    if (std::abs(jump) <= min_jump || jump * from_zero >= 0) continue;  // only jumps back toward the zero
    SlipEvent e;
    e.row = i;
    e.position = position[i];
    e.jump = jump;
    e.normal_force = 0.5 * (normal_force[i] + normal_force[i + 1]);
    e.load_resolution = 0.5 * std::abs(normal_force[i] - normal_force[i + 1]);
    e.friction_force = stiffness * std::abs(from_zero);
    events.push_back(e);
  }
  return events;
}

FrictionLine friction_line(double a, double b, const Eigen::Matrix2d& c, double rms_residual) {
  FrictionLine out;
  out.mu = b;
  out.mu_sigma = std::sqrt(c(1, 1));
  out.intercept = a;
  out.intercept_sigma = std::sqrt(c(0, 0));
  const double d = std::sqrt(c(0, 0) * c(1, 1));
  out.correlation = d > 0 ? c(0, 1) / d : 0.0;
  const double ga = 1 / b, gb = -a / (b * b);
  out.adhesion_force = a / b;
  out.adhesion_force_sigma = std::sqrt(std::max(0.0, ga * ga * c(0, 0) + gb * gb * c(1, 1) + 2 * ga * gb * c(0, 1)));
  out.rms_residual = rms_residual;
  return out;
}

StaticFit fit_static(std::vector<SlipEvent> events, const std::string& what, double min_jump) {
  using tools::BadInput;
  char jump[32];
  std::snprintf(jump, sizeof jump, "%g nm", min_jump * 1e9);
  if (events.empty())
    throw BadInput(what + ": no slip event found (no position jump larger than " + std::string(jump) +
                   " toward the spring zero); lower --min-jump or check --zero-position");
  if (events.size() < 3)
    throw BadInput(what + ": only " + std::to_string(events.size()) + " slip event(s) larger than " + jump +
                   "; Eq. 2.2 needs at least 3 to fit mu_s and F_adh with uncertainties (ramp further or lower --min-jump)");
  std::vector<double> fn, fs;
  for (const auto& e : events) {
    fn.push_back(e.normal_force);
    fs.push_back(e.friction_force);
  }
  StaticFit out;
  out.events = std::move(events);
  const tools::FitResult line = tools::fit_line(fn, fs);
  out.line = friction_line(line.parameters(0), line.parameters(1), line.covariance, line.rms_residual);
  return out;
}

}  // namespace tribex::friction_test
