// SPDX-License-Identifier: MIT
#include "tools/friction_test/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tools/common/errors.hpp"

namespace tribex::friction_test {

std::vector<std::size_t> centre_crossings(const std::vector<double>& x, double centre, double band) {
  std::vector<std::size_t> out;
  int side = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = x[i] - centre;
    const int now = d > band ? 1 : (d < -band ? -1 : 0);
    if (now != 0 && side != 0 && now != side) {
      std::size_t j = i;  // walk back to the last sample still on the old side
      while (j > 0 && (x[j - 1] - centre) * now > 0) --j;
      if (j > 0) out.push_back(j);
    }
    if (now != 0) side = now;
  }
  return out;
}

double crossing_frequency(const std::vector<double>& t, const std::vector<double>& x, double centre, double band) {
  std::vector<double> crossings;  // located by linear interpolation
  for (std::size_t j : centre_crossings(x, centre, band)) {
    const double d0 = x[j - 1] - centre, d1 = x[j] - centre;
    crossings.push_back(t[j - 1] + (t[j] - t[j - 1]) * d0 / (d0 - d1));
  }
  if (crossings.size() < 3) return 0.0;
  return std::numbers::pi * static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
}

double RingdownFit::position(double t) const {
  const auto& p = fit.parameters;
  const double tau = t - t0;
  return p(0) + std::exp(-p(3) * tau) * (p(1) * std::cos(p(4) * tau) + p(2) * std::sin(p(4) * tau));
}

RingdownFit fit_ringdown(const std::vector<double>& t, const std::vector<double>& x, const std::string& what) {
  using tools::BadInput;
  const std::size_t n = t.size();
  if (n < 20) throw BadInput(what + ": " + std::to_string(n) + " samples; a ringdown fit needs at least 20");
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  const double half_range = (*hi - *lo) / 2;
  const double omega_d = crossing_frequency(t, x, mean, 0.1 * half_range);
  if (omega_d <= 0 || (t.back() - t.front()) * omega_d < 4 * std::numbers::pi)
    throw BadInput(what + ": the position does not oscillate (fewer than two full cycles about its mean); "
                   "record a longer ringdown");
  // Decay rate from the rms of the first and last quarter of the record about the mean.
  auto rms = [&](std::size_t a, std::size_t b) {
    double s = 0;
    for (std::size_t i = a; i < b; ++i) s += (x[i] - mean) * (x[i] - mean);
    return std::sqrt(s / static_cast<double>(b - a));
  };
  const double r0 = rms(0, n / 4), r1 = rms(3 * n / 4, n);
  const double span = t[3 * n / 4] - t[0];
  double sigma = r1 > 0 && r0 > r1 ? std::log(r0 / r1) / span : 1.0 / (t.back() - t.front());
  sigma = std::min(sigma, 0.5 * omega_d);

  RingdownFit out;
  out.t0 = t.front();
  // With omega_d and sigma fixed the model is linear in (x_eq, a, b): solve it for the start.
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double tau = t[i] - out.t0, e = std::exp(-sigma * tau);
    const auto r = static_cast<Eigen::Index>(i);
    a(r, 0) = 1;
    a(r, 1) = e * std::cos(omega_d * tau);
    a(r, 2) = e * std::sin(omega_d * tau);
    b(r) = x[i];
  }
  const Eigen::Vector3d lin = a.colPivHouseholderQr().solve(b);
  Eigen::VectorXd start(5);
  start << lin(0), lin(1), lin(2), sigma, omega_d;
  Eigen::VectorXd scale(5);
  const double amp = std::max(half_range, 1e-12);
  scale << amp, amp, amp, omega_d * 1e-3, omega_d;
  auto residuals = [&](const Eigen::VectorXd& p) -> std::optional<Eigen::VectorXd> {
    if (p(3) < 0 || p(4) <= 0) return std::nullopt;
    Eigen::VectorXd r(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      const double tau = t[i] - out.t0;
      r(static_cast<Eigen::Index>(i)) =
          p(0) + std::exp(-p(3) * tau) * (p(1) * std::cos(p(4) * tau) + p(2) * std::sin(p(4) * tau)) - x[i];
    }
    return r;
  };
  out.fit = tools::levenberg_marquardt(residuals, start, scale);
  const auto& p = out.fit.parameters;
  const auto& c = out.fit.covariance;
  out.x_eq = p(0);
  out.sigma = p(3);
  out.omega_d = p(4);
  out.x_eq_sigma = std::sqrt(c(0, 0));
  out.sigma_sigma = std::sqrt(c(3, 3));
  out.omega_d_sigma = std::sqrt(c(4, 4));
  out.omega0 = std::sqrt(p(4) * p(4) + p(3) * p(3));
  // omega0 = sqrt(omega_d^2 + sigma^2): gradient (omega_d, sigma) / omega0 through the covariance.
  const double gw = p(4) / out.omega0, gs = p(3) / out.omega0;
  out.omega0_sigma = std::sqrt(gw * gw * c(4, 4) + gs * gs * c(3, 3) + 2 * gw * gs * c(3, 4));
  out.quality = out.sigma > 0 ? out.omega0 / (2 * out.sigma) : 0.0;
  // Q = omega0/(2 sigma): relative errors add in quadrature (omega0 and sigma nearly uncorrelated).
  if (out.sigma > 0)
    out.quality_sigma = out.quality * std::hypot(out.omega0_sigma / out.omega0, out.sigma_sigma / out.sigma);
  out.amplitude = std::hypot(p(1), p(2));
  out.rms_residual = out.fit.rms_residual;
  return out;
}

double ResonanceFit::amplitude(double omega) const {
  const auto& p = fit.parameters;
  const double d = p(1) * p(1) - omega * omega;
  return p(0) / std::sqrt(d * d + 4 * p(2) * p(2) * omega * omega);
}

ResonanceFit fit_resonance(const std::vector<double>& omega, const std::vector<double>& amplitude,
                           const std::string& what) {
  using tools::BadInput;
  const std::size_t n = omega.size();
  if (n < 10) throw BadInput(what + ": " + std::to_string(n) + " points; a resonance fit needs at least 10");
  const auto peak = static_cast<std::size_t>(std::max_element(amplitude.begin(), amplitude.end()) - amplitude.begin());
  if (peak == 0 || peak + 1 == n)
    throw BadInput(what + ": the amplitude peaks at the end of the sweep; sweep across the resonance");
  const double w0 = omega[peak], a_max = amplitude[peak];
  // Half-power points on either side of the peak (amplitude a_max / sqrt 2).
  std::size_t lo = peak, hi = peak;
  while (lo > 0 && amplitude[lo] > a_max / std::sqrt(2.0)) --lo;
  while (hi + 1 < n && amplitude[hi] > a_max / std::sqrt(2.0)) ++hi;
  const double sigma = std::max(0.5 * (omega[hi] - omega[lo]) / 2, 1e-6 * w0);
  ResonanceFit out;
  Eigen::VectorXd start(3), scale(3);
  start << a_max * 2 * sigma * w0, w0, sigma;  // at resonance X = (F0/m) / (2 sigma omega0)
  scale << start(0), w0, sigma;
  auto residuals = [&](const Eigen::VectorXd& p) -> std::optional<Eigen::VectorXd> {
    if (p(1) <= 0 || p(2) <= 0) return std::nullopt;
    Eigen::VectorXd r(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      const double d = p(1) * p(1) - omega[i] * omega[i];
      r(static_cast<Eigen::Index>(i)) = p(0) / std::sqrt(d * d + 4 * p(2) * p(2) * omega[i] * omega[i]) - amplitude[i];
    }
    return r;
  };
  out.fit = tools::levenberg_marquardt(residuals, start, scale);
  const auto& p = out.fit.parameters;
  out.omega0 = p(1);
  out.sigma = p(2);
  out.omega0_sigma = out.fit.sigma(1);
  out.sigma_sigma = out.fit.sigma(2);
  out.quality = out.omega0 / (2 * out.sigma);
  out.quality_sigma = out.quality * std::hypot(out.omega0_sigma / out.omega0, out.sigma_sigma / out.sigma);
  out.rms_residual = out.fit.rms_residual;
  return out;
}

Stiffness stiffness_from_frequency(double omega0, double omega0_sigma, double mass, double mass_sigma) {
  Stiffness k;
  k.value = mass * omega0 * omega0;  // Eq. 2.4
  k.sigma = k.value * std::hypot(mass_sigma / mass, 2 * omega0_sigma / omega0);
  return k;
}

double folded_spring_stiffness(double youngs_modulus, double thickness, double width, double length, int folds) {
  const double k_beam = youngs_modulus * thickness * width * width * width / (length * length * length);
  return 0.5 * folds * k_beam;
}

}  // namespace tribex::friction_test
