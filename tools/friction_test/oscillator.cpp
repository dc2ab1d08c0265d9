// SPDX-License-Identifier: MIT
#include "tools/friction_test/oscillator.hpp"

#include <cmath>
#include <numbers>

namespace tribex::friction_test {
namespace {

constexpr double pi = std::numbers::pi;

bool valid(const OscillatorParams& p) {
  return p.omega0 > 0 && p.sigma >= 0 && p.sigma < p.omega0 && p.coulomb_offset >= 0 && std::isfinite(p.x_eq);
}

// One moving segment from (x, v) with direction s: the closed form of oscillator.hpp.
struct Segment {
  double s, y0, v0, sigma, omega0, omega_d, duration;
  double y(double tau) const {
    const double e = std::exp(-sigma * tau);
    return e * (y0 * std::cos(omega_d * tau) + (v0 + sigma * y0) / omega_d * std::sin(omega_d * tau));
  }
};

Segment make_segment(const OscillatorParams& p, double x_rel, double v, double s) {
  Segment g{};
  g.s = s;
  g.y0 = x_rel + s * p.coulomb_offset;
  g.v0 = v;
  g.sigma = p.sigma;
  g.omega0 = p.omega0;
  g.omega_d = std::sqrt(p.omega0 * p.omega0 - p.sigma * p.sigma);
  // x' = R e^{-sigma t} cos(omega_d t + phi) with R cos phi = v0, R sin phi = (omega0^2 y0 + sigma v0)/omega_d.
  const double phi = std::atan2((p.omega0 * p.omega0 * g.y0 + p.sigma * v) / g.omega_d, v);
  double theta = pi / 2 - phi;  // in [-pi/2, 3pi/2)
  while (theta <= 1e-12) theta += pi;
  while (theta > pi + 1e-12) theta -= pi;
  g.duration = theta / g.omega_d;
  return g;
}

// Direction of motion from rest at x_rel = x - x_eq, or 0 when static friction holds it.
double start_direction(const OscillatorParams& p, double x_rel) {
  const double hold = std::max(p.stick_offset, p.coulomb_offset);
  if (std::abs(x_rel) <= hold) return 0.0;
  return x_rel > 0 ? -1.0 : 1.0;
}

}  // namespace

bool oscillator_positions(const OscillatorParams& p, const OscillatorStart& start,
                          const std::vector<double>& times, std::vector<double>& x_out) {
  x_out.assign(times.size(), 0.0);
  if (!valid(p)) return false;
  double t = start.t0, x_rel = start.x0 - p.x_eq, v = start.v0;
  double s = v > 0 ? 1.0 : (v < 0 ? -1.0 : start_direction(p, x_rel));
  std::size_t i = 0;
  while (i < times.size() && times[i] < t) x_out[i++] = start.x0;  // before the start: not defined, hold
  int guard = 0;
  while (i < times.size()) {
    if (s == 0.0) {  // stuck for good: nothing drives it again
      for (; i < times.size(); ++i) x_out[i] = p.x_eq + x_rel;
      break;
    }
    const Segment g = make_segment(p, x_rel, v, s);
    const double t_end = t + g.duration;
    for (; i < times.size() && times[i] <= t_end; ++i) x_out[i] = p.x_eq - s * p.coulomb_offset + g.y(times[i] - t);
    x_rel = -s * p.coulomb_offset + g.y(g.duration);
    v = 0.0;
    t = t_end;
    s = start_direction(p, x_rel);
    if (++guard > 10000000) return false;
  }
  return true;
}

StopPoint oscillator_stop(const OscillatorParams& p, double x0, int max_reversals) {
  StopPoint out{x0, 0.0, 0};
  if (!valid(p)) return out;
  double x_rel = x0 - p.x_eq;
  for (double s = start_direction(p, x_rel); s != 0.0 && out.reversals < max_reversals;
       s = start_direction(p, x_rel)) {
    const Segment g = make_segment(p, x_rel, 0.0, s);
    x_rel = -s * p.coulomb_offset + g.y(g.duration);
    out.time += g.duration;
    ++out.reversals;
  }
  out.x = p.x_eq + x_rel;
  return out;
}

}  // namespace tribex::friction_test
