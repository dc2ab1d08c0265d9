// SPDX-License-Identifier: MIT
#include "tools/friction_test/dynamic_friction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tools/common/errors.hpp"
#include "tools/friction_test/calibration.hpp"
#include "tools/friction_test/static_friction.hpp"

namespace tribex::friction_test {
namespace {

constexpr double pi = std::numbers::pi;

// First guesses from the record itself. omega_d: centre crossings. Then the reversal extremes
// e_n (the largest |x - centre| between successive crossings) obey, by one half cycle of the
// closed form in oscillator.hpp with a_n = e_n - x_eq and rho = exp(-sigma pi / omega_d),
//     a_{n+1} = -rho a_n + sign(a_n) delta (1 + rho),
// i.e. e_{n+1} = x_eq (1 + rho) - rho e_n + sign(a_n) delta (1 + rho): linear least squares in
// (x_eq (1 + rho), rho, delta (1 + rho)) gives x_eq, sigma and delta.
struct Guess {
  double x_eq, omega_d, sigma, delta;
};

Guess first_guess(const std::vector<double>& t, const std::vector<double>& x, const std::string& what) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  Guess g{};
  const double centre = 0.5 * (*lo + *hi), half_range = 0.5 * (*hi - *lo);
  g.x_eq = centre;
  g.omega_d = crossing_frequency(t, x, centre, 0.05 * half_range);
  if (g.omega_d <= 0)
    throw tools::BadInput(what + ": the position does not oscillate about its mid-range (fewer than 3 crossings); "
                          "a dynamic-friction record must start at the slip and cover several cycles");
  const auto cross = centre_crossings(x, centre, 0.05 * half_range);
  std::vector<double> extremes, signs;
  for (std::size_t c = 0; c + 1 < cross.size(); ++c) {
    std::size_t best = cross[c];
    for (std::size_t i = cross[c]; i < cross[c + 1]; ++i)
      if (std::abs(x[i] - centre) > std::abs(x[best] - centre)) best = i;
    extremes.push_back(x[best]);
    signs.push_back(x[best] > centre ? 1.0 : -1.0);
  }
  g.sigma = 1e-3 * g.omega_d;
  g.delta = 0.01 * half_range;
  if (extremes.size() >= 4) {
    const auto m = static_cast<Eigen::Index>(extremes.size() - 1);
    Eigen::MatrixXd a(m, 3);
    Eigen::VectorXd b(m);
    for (Eigen::Index k = 0; k < m; ++k) {
      const auto u = static_cast<std::size_t>(k);
      a(k, 0) = 1.0;
      a(k, 1) = -extremes[u];
      a(k, 2) = signs[u];
      b(k) = extremes[u + 1];
    }
    const Eigen::Vector3d q = a.colPivHouseholderQr().solve(b);
    const double rho = std::clamp(q(1), 0.05, 0.9999);
    g.x_eq = q(0) / (1 + rho);
    g.sigma = -std::log(rho) * g.omega_d / pi;
    if (q(2) > 0) g.delta = q(2) / (1 + rho);
  }
  return g;
}

}  // namespace

DynamicFit fit_dynamic(const std::vector<double>& t, const std::vector<double>& x, const Calibration& cal,
                       const std::string& what) {
  const std::size_t n = t.size();
  if (n < 30) throw tools::BadInput(what + ": " + std::to_string(n) + " samples; a dynamic fit needs at least 30");
  const Guess g = first_guess(t, x, what);

  // Start state: a parabola x0 + v0 tau + b tau^2 through the first eighth of a cycle (error
  // O(tau^3) of the motion), good enough for LM to take over.
  const double dt_avg = (t.back() - t.front()) / static_cast<double>(n - 1);
  const auto m = static_cast<Eigen::Index>(std::clamp<std::size_t>(static_cast<std::size_t>(pi / 4 / g.omega_d / dt_avg), 4, n));
  Eigen::MatrixXd pa(m, 3);
  Eigen::VectorXd pb(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double tau = (t[static_cast<std::size_t>(i)] - t.front()) * g.omega_d;
    pa(i, 0) = 1;
    pa(i, 1) = tau;
    pa(i, 2) = tau * tau;
    pb(i) = x[static_cast<std::size_t>(i)];
  }
  const Eigen::Vector3d parabola = pa.colPivHouseholderQr().solve(pb);
  const double x0 = parabola(0), v0 = parabola(1) * g.omega_d;

  // Static friction F_s > F_d stops the device earlier than pure Coulomb friction would. A
  // record cannot pin F_s down (any value between the last two reversal swings gives the same
  // stop), so when the record ends at rest (the last half period moves less than 3% of the first)
  // the model sticks at a reversal with |x - x_eq| <= max(delta, |x_rest - x_eq| + eps): pure
  // Coulomb sticking when that explains the rest position, else just above the observed final
  // swing. eps = 0.05 delta plus 3 standard errors of x_rest keeps the noise from deciding it;
  // the previous swing is larger by (1 + rho)(|a_{N-1}| - delta), almost always far more.
  const double first_range = [&] {
    double lo = x.front(), hi = x.front();
    for (std::size_t i = 0; i < n && t[i] - t.front() < pi / g.omega_d; ++i) lo = std::min(lo, x[i]), hi = std::max(hi, x[i]);
    return hi - lo;
  }();
  double tail_lo = x.back(), tail_hi = x.back(), tail_sum = 0, tail_sq = 0;
  std::size_t tail_n = 0;
  for (std::size_t i = n; i-- > 0 && t.back() - t[i] < pi / g.omega_d;) {
    tail_lo = std::min(tail_lo, x[i]);
    tail_hi = std::max(tail_hi, x[i]);
    tail_sum += x[i];
    tail_sq += x[i] * x[i];
    ++tail_n;
  }
  const bool ends_at_rest = tail_n >= 5 && tail_hi - tail_lo < 0.03 * first_range;
  const double tail_count = static_cast<double>(std::max<std::size_t>(tail_n, 1));
  const double x_rest = tail_sum / tail_count;
  const double rest_error = std::sqrt(std::max(0.0, tail_sq / tail_count - x_rest * x_rest) / tail_count);

  auto params = [&](const Eigen::VectorXd& p) {
    OscillatorParams o;
    o.omega0 = p(0);
    o.sigma = p(1);
    o.coulomb_offset = p(2);
    o.stick_offset = ends_at_rest ? std::max(p(2), std::abs(x_rest - p(3)) + 0.05 * p(2) + 3 * rest_error) : p(2);
    o.x_eq = p(3);
    return o;
  };
  // Residuals over the first `used` samples: the fit is continued over a growing window (2, 4,
  // 8, ... cycles, then all) because a frequency error of 0.3% from the crossings is already a
  // quarter radian of phase after 14 cycles, enough to trap LM in a wrong minimum.
  std::size_t used = n;
  std::vector<double> t_used;
  auto residuals = [&](const Eigen::VectorXd& p) -> std::optional<Eigen::VectorXd> {
    std::vector<double> model;
    if (!oscillator_positions(params(p), {t.front(), p(4), p(5)}, t_used, model)) return std::nullopt;
    Eigen::VectorXd r(static_cast<Eigen::Index>(used));
    for (std::size_t i = 0; i < used; ++i) r(static_cast<Eigen::Index>(i)) = model[i] - x[i];
    return r;
  };
  const double half_range = 0.5 * (*std::max_element(x.begin(), x.end()) - *std::min_element(x.begin(), x.end()));
  Eigen::VectorXd start(6), scale(6);
  start << std::sqrt(g.omega_d * g.omega_d + g.sigma * g.sigma), g.sigma, g.delta, g.x_eq, x0, v0;
  scale << g.omega_d, g.omega_d * 1e-2, half_range * 1e-2, half_range, half_range, half_range * g.omega_d;
  DynamicFit out;
  const double period = 2 * pi / g.omega_d;
  for (double cycles = 2;; cycles *= 2) {
    used = n;
    while (used > 30 && t[used - 1] - t.front() > cycles * period) --used;
    t_used.assign(t.begin(), t.begin() + static_cast<long>(used));
    out.fit = tools::levenberg_marquardt(residuals, start, scale);
    start = out.fit.parameters;
    if (used == n) break;
  }
  const auto& p = out.fit.parameters;
  const auto& c = out.fit.covariance;
  out.oscillator = params(p);
  out.start = {t.front(), p(4), p(5)};
  out.omega0_sigma = std::sqrt(c(0, 0));
  out.sigma_sigma = std::sqrt(c(1, 1));
  out.coulomb_offset_sigma = std::sqrt(c(2, 2));
  out.x_eq_sigma = std::sqrt(c(3, 3));
  out.rms_residual = out.fit.rms_residual;
  out.samples = n;
  out.ends_at_rest = ends_at_rest;
  oscillator_positions(out.oscillator, out.start, t, out.model);

  const double w = p(0), s = p(1), d = p(2);
  const double rel_w = out.omega0_sigma / w, rel_s = s > 0 ? out.sigma_sigma / s : 0.0,
               rel_d = d > 0 ? out.coulomb_offset_sigma / d : 0.0;
  out.quality = s > 0 ? w / (2 * s) : 0.0;
  if (cal.stiffness > 0) {
    const double rel_k = cal.stiffness_sigma / cal.stiffness;
    out.stiffness = cal.stiffness;
    out.stiffness_sigma = cal.stiffness_sigma;
    out.mass = cal.stiffness / (w * w);
    out.mass_sigma = out.mass * std::hypot(rel_k, 2 * rel_w);
    out.friction_force = cal.stiffness * d;
    out.friction_force_sigma = out.friction_force * std::hypot(rel_k, rel_d);
    out.damping = 2 * cal.stiffness * s / (w * w);
    out.damping_sigma = out.damping * std::sqrt(rel_k * rel_k + rel_s * rel_s + 4 * rel_w * rel_w);
  } else {
    const double rel_m = cal.mass_sigma / cal.mass;
    out.mass = cal.mass;
    out.mass_sigma = cal.mass_sigma;
    out.stiffness = cal.mass * w * w;
    out.stiffness_sigma = out.stiffness * std::hypot(rel_m, 2 * rel_w);
    out.friction_force = out.stiffness * d;
    // F_d = m w^2 delta: w and delta come from the same fit; their correlation is small next to
    // the mass term but is kept: var(ln F) = rel_m^2 + 4 rel_w^2 + rel_d^2 + 4 corr rel_w rel_d.
    const double corr = out.fit.correlation(0, 2);
    out.friction_force_sigma =
        out.friction_force * std::sqrt(std::max(0.0, rel_m * rel_m + 4 * rel_w * rel_w + rel_d * rel_d +
                                                        4 * corr * rel_w * rel_d));
    out.damping = 2 * cal.mass * s;
    out.damping_sigma = out.damping * std::hypot(rel_m, rel_s);
  }
  return out;
}

FrictionLine fit_load_line(const std::vector<double>& normal_force, const std::vector<double>& friction_force,
                       const std::vector<double>& friction_force_sigma) {
  const tools::FitResult line = tools::fit_line(normal_force, friction_force);
  const double a = line.parameters(0), b = line.parameters(1);
  Eigen::Matrix2d c = line.covariance;
  if (friction_force_sigma.size() == normal_force.size()) {
    Eigen::Matrix2d atwa = Eigen::Matrix2d::Zero();
    for (std::size_t i = 0; i < normal_force.size(); ++i) {
      const double w = 1.0 / (friction_force_sigma[i] * friction_force_sigma[i]);
      const Eigen::Vector2d row(1.0, normal_force[i]);
      atwa += w * row * row.transpose();
    }
    const Eigen::Matrix2d propagated = atwa.inverse();
    if (propagated(1, 1) > c(1, 1)) c = propagated;
  }
  return friction_line(a, b, c, line.rms_residual);
}

}  // namespace tribex::friction_test
