// SPDX-License-Identifier: MIT
#include "tools/pstd/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tribex::pstd {

Segment place_in_point_contact(const std::vector<double>& substrate, std::vector<double> counterface_z,
                               std::size_t start, int copy) {
  const std::size_t n = substrate.size();
  double lift = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < counterface_z.size(); ++i)
    lift = std::max(lift, substrate[(start + i) % n] - counterface_z[i]);
  for (double& z : counterface_z) z += lift;
  return Segment{std::move(counterface_z), start % n, copy};
}

void Gap::set_travel(std::size_t travel) {
  const auto& sub = model_.substrate;
  const std::size_t n = sub.size();
  offsets_.assign(1, 0);
  std::size_t total = 0;
  for (const auto& s : model_.segments) offsets_.push_back(total += s.z.size());
  d_.resize(total);
  highest_ = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < model_.segments.size(); ++k) {
    const auto& seg = model_.segments[k];
    double* d = d_.data() + offsets_[k];
    const double* zc = seg.z.data();
    const std::size_t len = seg.z.size();
    // Two contiguous pieces (before and after the periodic wrap) so that the loops vectorise.
    std::size_t j = (seg.start + travel) % n;
    std::size_t done = 0;
    double top = highest_;
    while (done < len) {
      const std::size_t piece = std::min(len - done, n - j);
      const double* zs = sub.data() + j;
      for (std::size_t i = 0; i < piece; ++i) d[done + i] = zs[i] - zc[done + i];
      for (std::size_t i = 0; i < piece; ++i) top = d[done + i] > top ? d[done + i] : top;
      done += piece;
      j = 0;
    }
    highest_ = top;
  }
  summits_.clear();
  threshold_ = highest_;
}

void Gap::collect(double threshold) {
  summits_.clear();
  threshold_ = threshold;
  const long m = model_.curvature_span;
  const double h2 = std::pow(static_cast<double>(m) * model_.dx, 2);
  for (std::size_t k = 0; k + 1 < offsets_.size(); ++k) {
    const double* d = d_.data() + offsets_[k];
    const long n = static_cast<long>(offsets_[k + 1] - offsets_[k]);
    for (long i = 0; i < n; ++i) {
      if (!(d[i] > threshold)) continue;
      // Summit: strictly above everything to its left and not below anything to its right within +-m,
      // so a flat top yields exactly one summit.
      bool summit = true;
      for (long j = std::max(0L, i - m); j < i && summit; ++j) summit = d[i] > d[j];
      for (long j = i + 1; j <= std::min(n - 1, i + m) && summit; ++j) summit = d[i] >= d[j];
      if (!summit) continue;
      double curvature = 0.0;
      if (n > 2 * m) {
        const long c = std::clamp(i, m, n - 1 - m);
        curvature = -(d[c + m] - 2.0 * d[c] + d[c - m]) / h2;
      }
      const double radius = curvature > 1.0 / model_.radius_cap ? 1.0 / curvature : model_.radius_cap;
      summits_.push_back(Summit{d[i], radius, k, static_cast<std::size_t>(i)});
    }
  }
  std::sort(summits_.begin(), summits_.end(), [](const Summit& a, const Summit& b) {
    return a.d != b.d ? a.d > b.d : (a.segment != b.segment ? a.segment < b.segment : a.index < b.index);
  });
}

ContactState Gap::evaluate(double height) const {
  const Mechanics& mech = model_.mechanics;
  ContactState s;
  double width_sum = 0.0;
  for (const auto& summit : summits_) {
    const double delta = summit.d - height;
    if (!(delta > 0.0)) break;  // sorted highest first
    const double r = summit.radius;
    double a = 0.0;
    if (mech.law == ContactLaw::line_2d) {
      bool clamped = false;
      a = line_contact_half_width(delta, r, &clamped);
      s.clamped += clamped ? 1 : 0;
      s.force += mech.depth * line_contact_load(a, r, mech.modulus);
      s.force_rate += mech.depth * line_contact_stiffness(a, r, mech.modulus);
      s.area += mech.depth * 2.0 * a;
      // d(2a)/d(delta) = 2 R' / (a (ln(4R'/a) - 1)), from d(delta)/da = (a/R')(ln(4R'/a) - 1).
      const double denom = a * (std::log(4.0 * r / a) - 1.0);
      s.area_rate += denom > 0.0 ? mech.depth * 2.0 * r / denom : 0.0;
    } else {
      a = hertz_half_width(delta, r);
      s.force += hertz_load(delta, r, mech.modulus);
      s.force_rate += hertz_stiffness(delta, r, mech.modulus);
      s.area += std::numbers::pi * a * a;  // pi a^2 = pi R' delta
      s.area_rate += std::numbers::pi * r;
    }
    width_sum += a;
    s.max_interference = std::max(s.max_interference, delta);
    ++s.contacts;
  }
  s.mean_half_width = s.contacts > 0 ? width_sum / s.contacts : 0.0;
  return s;
}

namespace {

/// Root of a decreasing function value(H) = target on [lo, hi] with value(lo) >= target > value(hi):
/// Newton steps (slope from `rate`), bisection whenever Newton leaves the bracket. With `strictly_below`
/// the returned H has value(H) < target; otherwise it is the iterate closest to the target.
template <class Value>
double solve_decreasing(Value value, double lo, double hi, double target, bool strictly_below) {
  const double rtol = 1e-13;
  double t = lo;
  double best = hi, best_error = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 200; ++it) {
    const auto [v, rate] = value(t);  // rate = -dv/dH >= 0
    if (v >= target) lo = t; else hi = t;
    const bool close = std::abs(v - target) <= rtol * target;
    if (close && (!strictly_below || v < target)) return t;
    if (std::abs(v - target) < best_error) { best = t; best_error = std::abs(v - target); }
    if (hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi)))
      break;
    double next = rate > 0.0 ? t + (v - target) / rate : 0.5 * (lo + hi);
    if (!(next > lo && next < hi) || next == t) next = 0.5 * (lo + hi);
    t = next;
  }
  return strictly_below ? hi : best;
}

}  // namespace

double height_for_force(Gap& gap, double force, double interference_guess) {
  if (!(force > 0.0)) throw std::invalid_argument("pstd: the normal force must be positive");
  const double top = gap.highest();
  double depth = std::max(interference_guess, 1e-12);
  for (int grow = 0;; ++grow) {  // bracket: F(top) = 0 < force <= F(top - depth)
    if (gap.collected_threshold() > top - depth) gap.collect(top - depth);
    if (gap.evaluate(top - depth).force >= force) break;
    if (grow > 200) throw std::runtime_error("pstd: could not bracket the normal force");
    depth *= 2.0;
  }
  return solve_decreasing(
      [&gap](double h) {
        const ContactState s = gap.evaluate(h);
        return std::pair{s.force, s.force_rate};
      },
      top - depth, top, force, false);
}

double height_for_area_below(Gap& gap, double height, double area) {
  if (gap.collected_threshold() > height) gap.collect(height);
  if (gap.evaluate(height).area < area) return height;
  return solve_decreasing(
      [&gap](double h) {
        const ContactState s = gap.evaluate(h);
        return std::pair{s.area, s.area_rate};
      },
      height, gap.highest(), area, true);
}

}  // namespace tribex::pstd
