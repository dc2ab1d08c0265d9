// SPDX-License-Identifier: MIT
#include "tools/fit/friction_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "solver/errors.hpp"

namespace tribex::fit {
namespace {

constexpr double pi = std::numbers::pi;

int index_of(const std::vector<std::string>& names, const std::string& n) {
  const auto it = std::find(names.begin(), names.end(), n);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

// tau minimising the residuals at fixed other parameters: F is linear in tau when alpha_p = 0.
std::optional<double> best_tau(const FrictionModel& model, FrictionParams p, const std::vector<double>& load,
                               const std::vector<double>& friction, Residual residual) {
  p.tau = 1.0;
  p.pressure_coefficient = 0.0;
  const auto unit = model.friction(p, load);
  if (!unit) return std::nullopt;
  double num = 0, den = 0, log_sum = 0;
  int n_log = 0;
  for (std::size_t i = 0; i < load.size(); ++i) {
    num += friction[i] * (*unit)[i];
    den += (*unit)[i] * (*unit)[i];
    if ((*unit)[i] > 0 && friction[i] > 0) {
      log_sum += std::log(friction[i] / (*unit)[i]);
      ++n_log;
    }
  }
  if (residual == Residual::relative && n_log > 0) return std::exp(log_sum / n_log);
  if (!(den > 0) || !(num > 0)) return std::nullopt;
  return num / den;
}

}  // namespace

double FrictionFit::sigma(const std::string& name) const {
  const int i = index_of(names, name);
  return i < 0 ? 0.0 : lm.sigma(i);
}

double FrictionFit::correlation(const std::string& a, const std::string& b) const {
  const int i = index_of(names, a), j = index_of(names, b);
  return i < 0 || j < 0 ? std::numeric_limits<double>::quiet_NaN() : lm.correlation(i, j);
}

FrictionFit fit_friction(const FrictionModel& model, const std::vector<double>& load,
                         const std::vector<double>& friction, Residual residual) {
  const double r = model.setup().radius;
  const double l_min = *std::min_element(load.begin(), load.end());
  const double l_max = *std::max_element(load.begin(), load.end());
  // Every model pulls off at |L_c| >= 1.5 pi W R, so this W puts every load in contact.
  const double w0 = l_min < 0 ? 1.25 * -l_min / (1.5 * pi * r) : 0.1 * std::max(l_max, 1e-12) / (pi * r);

  auto residuals = [&](const Eigen::VectorXd& v) -> std::optional<Eigen::VectorXd> {
    const auto f = model.friction(model.from_vector(v), load);
    if (!f) return std::nullopt;
    Eigen::VectorXd out(static_cast<Eigen::Index>(load.size()));
    for (std::size_t i = 0; i < load.size(); ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      if (residual == Residual::absolute) {
        out(k) = (*f)[i] - friction[i];
      } else {
        if (!((*f)[i] > 0)) return std::nullopt;
        out(k) = std::log((*f)[i] / friction[i]);
      }
    }
    return out;
  };

  std::optional<FrictionFit> best;
  std::string last_error = "no starting point had every load in contact";
  for (double w_start : {w0, 1.5 * w0, 3.0 * w0}) {
    FrictionParams p = model.defaults(0.0, w_start);
    if (!model.setup().cos_alpha) p.cos_alpha = 0.3;
    const auto tau0 = best_tau(model, p, load, friction, residual);
    if (!tau0) continue;
    p.tau = *tau0;
    const Eigen::VectorXd start = model.to_vector(p);
    Eigen::VectorXd scale = start.cwiseAbs();
    const auto names = model.free_names();
    for (Eigen::Index k = 0; k < scale.size(); ++k) {
      const auto& n = names[static_cast<std::size_t>(k)];
      if (n == "alpha_p") scale(k) = 0.1;
      if (n == "cos_alpha") scale(k) = 0.3;
    }
    try {
      FrictionFit f;
      f.lm = tools::levenberg_marquardt(residuals, start, scale);
      f.names = names;
      f.best = model.from_vector(f.lm.parameters);
      f.pull_off_load = model.pull_off_load(f.best);
      if (!best || f.lm.rms_residual < best->lm.rms_residual) best = std::move(f);
    } catch (const std::runtime_error& e) {
      last_error = e.what();
    }
  }
  if (!best) throw solver::NumericalFailure("the friction fit failed: " + last_error);
  return *best;
}

Combination tau_over_ec_power(const FrictionFit& fit, double exponent) {
  const double tau = fit.best.tau, ec = fit.best.coating_youngs;
  Combination c;
  c.exponent = exponent;
  c.value = tau / std::pow(ec, exponent);
  const int j = index_of(fit.names, "Ec");
  // d ln g = d ln tau - k d ln Ec
  double var = fit.lm.covariance(0, 0) / (tau * tau);
  if (j >= 0)
    var += exponent * exponent * fit.lm.covariance(j, j) / (ec * ec) -
           2.0 * exponent * fit.lm.covariance(0, j) / (tau * ec);
  c.sigma = c.value * std::sqrt(std::max(var, 0.0));
  return c;
}

Combination tau_over_ec_valley(const FrictionFit& fit) {
  const int j = index_of(fit.names, "Ec");
  if (j < 0) throw std::logic_error("tau_over_ec_valley needs a fit with Ec free");
  const double tau = fit.best.tau, ec = fit.best.coating_youngs;
  const double cov = fit.lm.covariance(0, j) / (tau * ec), var_ec = fit.lm.covariance(j, j) / (ec * ec);
  return tau_over_ec_power(fit, cov / var_ec);
}

ShortcutFit dmt_shortcut(const std::vector<double>& load, const std::vector<double>& friction, double radius,
                         double reduced_modulus) {
  std::vector<double> x, y;
  for (std::size_t i = 0; i < load.size(); ++i)
    if (friction[i] > 0) {
      x.push_back(load[i]);
      y.push_back(std::pow(friction[i], 1.5));
    }
  const tools::FitResult line = tools::fit_line(x, y);  // y = c + s L
  const double c = line.parameters(0), s = line.parameters(1);
  ShortcutFit out;
  // L-intercept -c/s = -2 pi W R.
  out.work_of_adhesion = c / s / (2.0 * pi * radius);
  out.tau = std::pow(4.0 * reduced_modulus * s / (3.0 * radius), 2.0 / 3.0) / pi;
  const double var_c = line.covariance(0, 0), var_s = line.covariance(1, 1), cov = line.covariance(0, 1);
  // W = c/(2 pi R s): dW/W = dc/c - ds/s;  tau ~ s^(2/3): dtau/tau = (2/3) ds/s.
  const double rel_w = var_c / (c * c) + var_s / (s * s) - 2.0 * cov / (c * s);
  out.work_sigma = std::abs(out.work_of_adhesion) * std::sqrt(std::max(rel_w, 0.0));
  out.tau_sigma = out.tau * (2.0 / 3.0) * std::sqrt(var_s) / std::abs(s);
  return out;
}

std::vector<double> synth_friction(const FrictionModel& model, const FrictionParams& p,
                                   const std::vector<double>& loads, double relative_noise, Residual kind,
                                   std::uint64_t seed) {
  auto f = model.friction(p, loads);
  if (!f) throw std::invalid_argument("synth_friction: a load lies below the model's pull-off load");
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double f_max = *std::max_element(f->begin(), f->end());
  for (double& v : *f) v += relative_noise * (kind == Residual::relative ? v : f_max) * normal(rng);
  return *f;
}

std::vector<double> load_ramp(double from, double to, int n) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(from + (to - from) * i / std::max(n - 1, 1));
  return out;
}

}  // namespace tribex::fit
