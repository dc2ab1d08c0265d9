// SPDX-License-Identifier: MIT
#include "tools/fit/friction_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "tools/common/errors.hpp"
#include "tools/fit/maugis_dugdale.hpp"

namespace tribex::fit {
namespace {

constexpr double pi = std::numbers::pi;

// Pietrement & Troyon (2000) fits to Maugis-Dugdale (docs/theory.md 9.1; lambda^1.4, not lambda^1/4).
double pt_pull_off_bar(double lambda) {
  if (std::isinf(lambda)) return -1.5;
  const double x = 4.04 * std::pow(lambda, 1.4);
  return -1.75 + 0.25 * (x - 1.0) / (x + 1.0);
}
double pt_radius_bar(double lambda) {
  if (std::isinf(lambda)) return 1.54 + 0.279;
  const double x = 2.28 * std::pow(lambda, 1.3);
  return 1.54 + 0.279 * (x - 1.0) / (x + 1.0);
}
// COS 1999: lambda = -0.924 ln(1 - 1.02 alpha); alpha >= 1/1.02 is the JKR end (lambda = inf).
double cos_lambda(double alpha) {
  const double q = 1.0 - 1.02 * alpha;
  return q > 0 ? -0.924 * std::log(q) : std::numeric_limits<double>::infinity();
}

// A one-entry cache: the md fit evaluates many loads at one lambda, and with --lambda always the same.
struct MaugisCache {
  double lambda = -1;
  std::optional<MaugisDugdale> md;
  const MaugisDugdale& get(double l) {
    if (!md || l != lambda) {
      md.emplace(l);
      lambda = l;
    }
    return *md;
  }
};
thread_local MaugisCache maugis_cache;

}  // namespace

std::optional<AreaModel> parse_area_model(const std::string& name) {
  if (name == "coated") return AreaModel::coated;
  if (name == "dmt") return AreaModel::dmt;
  if (name == "jkr") return AreaModel::jkr;
  if (name == "cos") return AreaModel::cos;
  if (name == "md") return AreaModel::maugis_dugdale;
  return std::nullopt;
}

std::string model_name(AreaModel m) {
  switch (m) {
    case AreaModel::coated: return "coated";
    case AreaModel::dmt: return "dmt";
    case AreaModel::jkr: return "jkr";
    case AreaModel::cos: return "cos";
    case AreaModel::maugis_dugdale: return "md";
  }
  return "?";
}

FrictionModel::FrictionModel(FrictionSetup setup) : s_(std::move(setup)) {
  using tools::BadInput;
  if (!(s_.radius > 0)) throw BadInput("--radius must be > 0 (the tip radius R, e.g. 27nm)");
  if (!(s_.youngs > 0) || !(s_.poisson > -1 && s_.poisson < 0.5))
    throw BadInput("--youngs must be > 0 and --poisson in (-1, 0.5)");
  if (s_.reduced_modulus && !(*s_.reduced_modulus > 0)) throw BadInput("--reduced-modulus must be > 0");
  if (s_.model == AreaModel::coated) {
    if (!(s_.coating_youngs > 0) || !(s_.coating_poisson > -1 && s_.coating_poisson < 0.5) ||
        !(s_.coating_thickness > 0))
      throw BadInput("--coating-youngs and --coating-thickness must be > 0 and --coating-poisson in (-1, 0.5)");
    if (!s_.area_law && !s_.table) throw BadInput("the coated model needs --coating-table FILE or --A and --b");
    area_law(s_.coating_youngs);  // throws when the ratio is outside the table
  } else if (s_.free_coating_modulus) {
    throw BadInput("--fit-coating-modulus applies to --model coated only");
  }
  if (s_.model == AreaModel::maugis_dugdale) {
    if (s_.md_lambda.has_value() == s_.md_z0.has_value())
      throw BadInput("--model md needs exactly one of --lambda (fixed Maugis parameter) or --z0 (lambda from W)");
    if (s_.md_lambda && !(*s_.md_lambda > 0)) throw BadInput("--lambda must be > 0");
    if (s_.md_z0 && !(*s_.md_z0 > 0)) throw BadInput("--z0 must be > 0 (the LJ equilibrium separation, e.g. 0.2nm)");
  } else if (s_.md_lambda || s_.md_z0) {
    throw BadInput("--lambda and --z0 apply to --model md only");
  }
  if (s_.cos_alpha && (s_.model != AreaModel::cos || !(*s_.cos_alpha >= 0 && *s_.cos_alpha <= 1)))
    throw BadInput("--alpha applies to --model cos only and must lie in [0, 1]");
  if (s_.pressure_dependent && s_.model == AreaModel::cos)
    throw BadInput("--pressure-dependent needs the contact pressure, which the COS area fit does not give; "
                   "use --model dmt, jkr, md or coated");
}

double FrictionModel::plane_strain_modulus() const { return s_.youngs / (1 - s_.poisson * s_.poisson); }
double FrictionModel::reduced_modulus() const {
  return s_.reduced_modulus ? *s_.reduced_modulus : plane_strain_modulus() / 2;
}

AreaLawConstants FrictionModel::area_law(double coating_youngs) const {
  if (s_.area_law) return *s_.area_law;
  const double ratio = coating_youngs / (1 - s_.coating_poisson * s_.coating_poisson) / plane_strain_modulus();
  return s_.table->at(ratio);
}

std::vector<std::string> FrictionModel::free_names() const {
  std::vector<std::string> n{s_.pressure_dependent ? "tau0" : "tau", "W"};
  if (s_.pressure_dependent) n.emplace_back("alpha_p");
  if (s_.model == AreaModel::cos && !s_.cos_alpha) n.emplace_back("cos_alpha");
  if (s_.free_coating_modulus) n.emplace_back("Ec");
  return n;
}

Eigen::VectorXd FrictionModel::to_vector(const FrictionParams& p) const {
  std::vector<double> v{p.tau, p.work_of_adhesion};
  if (s_.pressure_dependent) v.push_back(p.pressure_coefficient);
  if (s_.model == AreaModel::cos && !s_.cos_alpha) v.push_back(p.cos_alpha);
  if (s_.free_coating_modulus) v.push_back(p.coating_youngs);
  return Eigen::Map<Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

FrictionParams FrictionModel::from_vector(const Eigen::VectorXd& v) const {
  FrictionParams p = defaults(v(0), v(1));
  Eigen::Index k = 2;
  if (s_.pressure_dependent) p.pressure_coefficient = v(k++);
  if (s_.model == AreaModel::cos && !s_.cos_alpha) p.cos_alpha = v(k++);
  if (s_.free_coating_modulus) p.coating_youngs = v(k++);
  return p;
}

FrictionParams FrictionModel::defaults(double tau, double work_of_adhesion) const {
  FrictionParams p;
  p.tau = tau;
  p.work_of_adhesion = work_of_adhesion;
  p.cos_alpha = s_.cos_alpha.value_or(0.0);
  p.coating_youngs = s_.coating_youngs;
  return p;
}

double FrictionModel::lambda(const FrictionParams& p) const {
  if (s_.model == AreaModel::cos) return cos_lambda(p.cos_alpha);
  if (s_.model != AreaModel::maugis_dugdale) return std::numeric_limits<double>::quiet_NaN();
  if (s_.md_lambda) return *s_.md_lambda;
  // lambda = 2 sigma0 (R/(pi W K^2))^(1/3) with the LJ peak stress sigma0 = 16W/(9 sqrt3 z0) (docs/theory.md 6.5).
  const double k = 4.0 * reduced_modulus() / 3.0;
  const double sigma0 = 16.0 * p.work_of_adhesion / (9.0 * std::sqrt(3.0) * *s_.md_z0);
  return 2.0 * sigma0 * std::cbrt(s_.radius / (pi * p.work_of_adhesion * k * k));
}

double FrictionModel::pull_off_load(const FrictionParams& p) const {
  const double pwr = pi * p.work_of_adhesion * s_.radius;
  switch (s_.model) {
    case AreaModel::coated:
    case AreaModel::dmt: return -2.0 * pwr;
    case AreaModel::jkr: return -1.5 * pwr;
    case AreaModel::cos: return pt_pull_off_bar(lambda(p)) * pwr;
    case AreaModel::maugis_dugdale: return maugis_cache.get(lambda(p)).pull_off().p_bar * pwr;
  }
  return 0;
}

std::optional<ContactState> FrictionModel::contact(const FrictionParams& p, double load) const {
  const double w = p.work_of_adhesion, r = s_.radius;
  if (!(w > 0) || !std::isfinite(w)) return std::nullopt;
  const double k = 4.0 * reduced_modulus() / 3.0;  // K = 4E*/3
  ContactState c;
  switch (s_.model) {
    case AreaModel::coated: {
      if (!(p.coating_youngs > 0)) return std::nullopt;
      const double load_eff = load + 2.0 * pi * w * r;  // report 3.3: DMT-like effective load
      if (load_eff < 0) return std::nullopt;
      const double ebar = plane_strain_modulus();
      const double ebar_c = p.coating_youngs / (1 - s_.coating_poisson * s_.coating_poisson);
      if (!s_.area_law && !s_.table->covers(ebar_c / ebar)) return std::nullopt;
      const AreaLawConstants law = area_law(p.coating_youngs);
      const double hertz = pi * std::pow(3.0 * load_eff * r * (1.0 + ebar / ebar_c) / (4.0 * ebar), 2.0 / 3.0);
      const double f_deep = std::pow(2.0 / (1.0 + ebar / ebar_c), 2.0 / 3.0);
      const double p_tilde = load_eff / (ebar_c * s_.coating_thickness * s_.coating_thickness);
      const double f_power = p_tilde > 0 ? law.A * std::pow(p_tilde, law.b) : 1.0;
      c.area = hertz * std::min(1.0, std::max(f_deep, f_power));
      c.carried_load = load_eff;
      return c;
    }
    case AreaModel::dmt: {
      const double load_eff = load + 2.0 * pi * w * r;
      if (load_eff < 0) return std::nullopt;
      c.area = pi * std::pow(r * load_eff / k, 2.0 / 3.0);
      c.carried_load = load_eff;
      return c;
    }
    case AreaModel::jkr: {
      const double q = 3.0 * pi * w * r;
      const double disc = 6.0 * pi * w * r * load + q * q;
      if (disc < 0) return std::nullopt;
      const double a = std::cbrt(r / k * (load + q + std::sqrt(disc)));
      c.area = pi * a * a;
      // JKR pressure p0 u^(1/2) - p1 u^(-1/2), u = 1 - r^2/a^2, p0 = 2aE*/(pi R), p1 = sqrt(2WE*/(pi a)),
      // integrated over the compressive part u >= p1/p0 (dA = pi a^2 du).
      const double e_star = reduced_modulus();
      const double p0 = 2.0 * a * e_star / (pi * r), p1 = std::sqrt(2.0 * w * e_star / (pi * a));
      const double u = std::min(1.0, p1 / p0);
      c.carried_load = pi * a * a * ((2.0 / 3.0) * p0 * (1.0 - std::pow(u, 1.5)) - 2.0 * p1 * (1.0 - std::sqrt(u)));
      return c;
    }
    case AreaModel::cos: {
      const double alpha = p.cos_alpha;
      if (!(alpha >= 0 && alpha <= 1)) return std::nullopt;
      const double lam = cos_lambda(alpha);
      const double l_c = pt_pull_off_bar(lam) * pi * w * r;
      if (load < l_c) return std::nullopt;
      const double a0 = pt_radius_bar(lam) * std::cbrt(pi * w * r * r / k);
      const double a = a0 * std::pow((alpha + std::sqrt(1.0 - load / l_c)) / (1.0 + alpha), 2.0 / 3.0);
      c.area = pi * a * a;
      c.carried_load = std::numeric_limits<double>::quiet_NaN();
      return c;
    }
    case AreaModel::maugis_dugdale: {
      const double lam = lambda(p);
      if (!(lam > 0) || !std::isfinite(lam)) return std::nullopt;
      const MaugisDugdale& md = maugis_cache.get(lam);
      const double load_bar = load / (pi * w * r);
      if (load_bar < md.pull_off().p_bar) return std::nullopt;
      const MaugisPoint pt = md.at_load(load_bar);
      const double a = pt.a_bar * std::cbrt(pi * w * r * r / k);
      c.area = pi * a * a;
      c.carried_load = pt.carried_bar(lam) * pi * w * r;
      return c;
    }
  }
  return std::nullopt;
}

std::optional<std::vector<double>> FrictionModel::friction(const FrictionParams& p,
                                                           const std::vector<double>& loads) const {
  std::vector<double> out;
  out.reserve(loads.size());
  for (double l : loads) {
    const auto c = contact(p, l);
    if (!c) return std::nullopt;
    double f = p.tau * c->area;
    if (s_.pressure_dependent) f += p.pressure_coefficient * std::max(c->carried_load, 0.0);
    out.push_back(f);
  }
  return out;
}

}  // namespace tribex::fit
