// SPDX-License-Identifier: MIT
#include "contact/models/rough_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "contact/rough/asperity_contact.hpp"
#include "contact/rough/hermite.hpp"
#include "contact/rough/gw_integrals.hpp"

namespace tribex::contact {
namespace {

// The continuous law from F_0, F_1, F_3/2 and dF_3/2/dt at t = d / sigma_s, with the scales of
// RoughSurfaceLaw::Scales (computed once: no pow or sqrt per call).
RoughSurfaceState continuous_state(const RoughSurfaceLaw::Scales& c, double f0, double f1, double f32, double df32) {
  RoughSurfaceState s;
  s.contact_density = c.count * f0;
  s.area_fraction = c.area * f1;
  s.adhesion = c.adhesion * f0;
  s.pressure = c.hertz * f32 - s.adhesion;
  s.stiffness = -c.hertz * df32 * c.inverse_sigma;  // dt/dd = 1/sigma_s
  return s;
}

// The attraction of the non-contacting area (rough/noncontact_attraction.hpp) on top of the contact
// part: it pulls like the DMT term (in `adhesion`, subtracted from p) and its slope counts in the
// stiffness of the stable step whatever its sign.
void add_noncontact(RoughSurfaceState& s, const NoncontactAttraction::Value& v) {
  s.noncontact = v.pressure;
  s.adhesion += v.pressure;
  s.pressure -= v.pressure;
  s.stiffness += std::abs(v.slope);
}

}  // namespace

RoughSurfaceLaw::RoughSurfaceLaw(RoughSurfaceParameters parameters) : parameters_(std::move(parameters)) {
  const auto& q = parameters_;
  if (!(q.composite_modulus > 0.0)) throw std::invalid_argument("rough surface: the composite modulus E* must be positive");
  if (!(q.work_of_adhesion >= 0.0)) throw std::invalid_argument("rough surface: the work of adhesion must be >= 0");
  if (!q.summit_heights.empty()) {
    if (q.summit_radii.size() != q.summit_heights.size())
      throw std::invalid_argument("rough surface: one radius per summit height is needed");
    if (!(q.map_area > 0.0)) throw std::invalid_argument("rough surface: the map area of the summit population must be positive");
    for (double r : q.summit_radii)
      if (!(r > 0.0)) throw std::invalid_argument("rough surface: summit radii must be positive");
    const double mean =
        std::accumulate(q.summit_heights.begin(), q.summit_heights.end(), 0.0) / static_cast<double>(q.summit_heights.size());
    std::vector<std::size_t> order(q.summit_heights.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return q.summit_heights[a] > q.summit_heights[b]; });
    for (std::size_t i : order) {
      heights_.push_back(q.summit_heights[i] - mean);
      radii_.push_back(q.summit_radii[i]);
    }
    contact_separation_ = heights_.front();
    return;
  }
  if (!(q.summit_density > 0.0 && q.summit_radius > 0.0 && q.sigma_s > 0.0))
    throw std::invalid_argument("rough surface: summit density, summit radius and sigma_s must be positive");
  scales_.count = q.summit_density;                                         // N/A_0 = eta F_0
  scales_.area = M_PI * q.summit_density * q.summit_radius * q.sigma_s;     // A_c/A_0 = pi eta R sigma_s F_1
  scales_.hertz = q.summit_density * (4.0 / 3.0) * q.composite_modulus * std::sqrt(q.summit_radius) *
                  std::pow(q.sigma_s, 1.5);                                 // p = (4/3) eta E* R^1/2 sigma_s^3/2 F_3/2
  scales_.adhesion = q.summit_density * 2.0 * M_PI * q.work_of_adhesion * q.summit_radius;  // - 2 pi W R eta F_0
  scales_.inverse_sigma = 1.0 / q.sigma_s;
  const int count = static_cast<int>(std::lround((table_t_max - table_t_min) / table_spacing)) + 1;
  for (int k = 0; k < count; ++k) {
    const double t = table_t_min + k * table_spacing;
    f0_.push_back(gw::gw_integral(0.0, t));
    f1_.push_back(gw::gw_integral(1.0, t));
    f32_.push_back(gw::gw_integral(1.5, t));
    df0_.push_back(-gw::normal_pdf(t));            // dF_0/dt = -phi(t)
    df1_.push_back(-f0_.back());                    // dF_1/dt = -F_0(t)
    df32_.push_back(-1.5 * gw::gw_integral(0.5, t));  // dF_n/dt = -n F_{n-1}(t)
  }
  contact_separation_ = table_t_max * q.sigma_s;
  if (q.noncontact_z0 > 0.0)
    noncontact_ = NoncontactAttraction({q.work_of_adhesion, q.noncontact_z0, q.noncontact_cutoff},
                                       q.surface_sigma > 0.0 ? q.surface_sigma : q.sigma_s);
}

RoughSurfaceState RoughSurfaceLaw::evaluate(double d) const {
  if (discrete()) return evaluate_direct(d);
  RoughSurfaceState s = contact_part(d);
  if (noncontact_.active()) add_noncontact(s, noncontact_.evaluate(d));
  return s;
}

RoughSurfaceState RoughSurfaceLaw::contact_part(double d) const {
  const double t = d * scales_.inverse_sigma;
  if (t >= table_t_max) return {};  // F_0(6) = 1e-9: no contact
  const int last = static_cast<int>(f0_.size()) - 1;
  if (t <= table_t_min) {
    // Far below the table (8 sigma_s into the summits): continue each F_n along its end tangent.
    const double dt = t - table_t_min;
    return continuous_state(scales_, f0_[0] + df0_[0] * dt, f1_[0] + df1_[0] * dt, f32_[0] + df32_[0] * dt, df32_[0]);
  }
  const double x = (t - table_t_min) / table_spacing;
  const int k = std::min(static_cast<int>(x), last - 1);
  const double s = x - k, h = table_spacing;
  const auto at = [&](const std::vector<double>& f, const std::vector<double>& df) {
    return hermite(s, f[k], f[k + 1], h * df[k], h * df[k + 1]);
  };
  const double df32 = hermite_slope(s, f32_[k], f32_[k + 1], h * df32_[k], h * df32_[k + 1]) / h;
  return continuous_state(scales_, at(f0_, df0_), at(f1_, df1_), at(f32_, df32_), df32);
}

RoughSurfaceState RoughSurfaceLaw::evaluate_direct(double d) const {
  const auto& q = parameters_;
  if (!discrete()) {
    const double t = d / q.sigma_s;
    RoughSurfaceState s = continuous_state(scales_, gw::gw_integral(0.0, t), gw::gw_integral(1.0, t),
                                           gw::gw_integral(1.5, t), -1.5 * gw::gw_integral(0.5, t));
    if (noncontact_.active()) add_noncontact(s, noncontact_.evaluate_direct(d));
    return s;
  }
  RoughSurfaceState s;
  double count = 0.0;
  for (std::size_t i = 0; i < heights_.size() && heights_[i] > d; ++i) {
    const auto a = gw::asperity_contact(heights_[i] - d, radii_[i], q.composite_modulus, q.work_of_adhesion);
    count += 1.0;
    s.area_fraction += a.area;
    s.pressure += a.force;
    s.adhesion += a.pull;
    s.stiffness += a.stiffness;
  }
  s.contact_density = count / q.map_area;
  s.area_fraction /= q.map_area;
  s.adhesion /= q.map_area;
  s.pressure = s.pressure / q.map_area - s.adhesion;
  s.stiffness /= q.map_area;
  return s;
}

}  // namespace tribex::contact
