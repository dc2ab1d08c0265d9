// SPDX-License-Identifier: MIT
#include "contact/rough/noncontact_attraction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/rough/gw_integrals.hpp"
#include "contact/rough/hermite.hpp"

namespace tribex::contact {
namespace {

constexpr double tails = 8.0;           // the Gaussian beyond 8 sigma is neglected (phi(8) = 5e-15)
constexpr double points_per_sigma = 50;  // table spacing sigma / 50 (Hermite error below 1e-7 of the value)

}  // namespace

NoncontactAttraction::NoncontactAttraction(const AdhesionLaw& law, double sigma) : law_(law), sigma_(sigma) {
  if (!(sigma > 0.0) || !(law.work > 0.0) || !(law.z0 > 0.0) || !(law.cutoff > law.z0))
    throw std::invalid_argument("non-contact attraction: sigma, W and z0 must be positive and the cut-off above z0");
  d_min_ = -tails * sigma;
  d_max_ = law.capture_gap() + tails * sigma;
  spacing_ = sigma / points_per_sigma;
  const int count = static_cast<int>(std::ceil((d_max_ - d_min_) / spacing_)) + 1;
  p_.resize(static_cast<std::size_t>(count));
  dp_.resize(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const Value v = evaluate_direct(d_min_ + k * spacing_);
    p_[static_cast<std::size_t>(k)] = v.pressure;
    dp_[static_cast<std::size_t>(k)] = v.slope;
  }
}

NoncontactAttraction::Value NoncontactAttraction::evaluate_direct(double d) const {
  // The gaps that carry weight: g in [d - 8 sigma, d + 8 sigma] within [0, g_c]; the law varies on the
  // scale z0 near g = 0, so that part gets its own panels.
  const double g_c = law_.capture_gap();
  const double lo = std::max(0.0, d - tails * sigma_), hi = std::min(g_c, d + tails * sigma_);
  Value v;
  if (!(hi > lo)) return v;
  const double near = std::min(hi, std::max(lo, 10.0 * law_.z0));
  auto integrate = [&](auto weight) {
    auto f = [&](double g) { return adhesive_traction(g, law_) * weight((d - g) / sigma_); };
    double sum = 0.0;
    if (near > lo) sum += gw::gauss_legendre(f, lo, near, 40);
    if (hi > near) sum += gw::gauss_legendre(f, near, hi, 60);
    return sum;
  };
  v.pressure = integrate([](double x) { return gw::normal_pdf(x); }) / sigma_;
  v.slope = integrate([](double x) { return -x * gw::normal_pdf(x); }) / (sigma_ * sigma_);
  return v;
}

NoncontactAttraction::Value NoncontactAttraction::evaluate(double d) const {
  if (!active() || d <= d_min_ || d >= d_max_) return {};
  const double x = (d - d_min_) / spacing_;
  const std::size_t k = std::min(static_cast<std::size_t>(x), p_.size() - 2);
  const double s = x - static_cast<double>(k), h = spacing_;
  const double m0 = h * dp_[k], m1 = h * dp_[k + 1];
  return {hermite(s, p_[k], p_[k + 1], m0, m1), hermite_slope(s, p_[k], p_[k + 1], m0, m1) / h};
}

}  // namespace tribex::contact
