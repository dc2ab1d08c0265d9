// SPDX-License-Identifier: MIT
// docs/theory.md 6.7.4-6.7.5: continuation of the sphere-flat equilibrium through both branches.
#include "tools/adhesion/curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <cstdio>
#include <cstdlib>

#include "solver/errors.hpp"

namespace tribex::adhesion {

double gap_length(const Problem& pb, double a) {
  const double z0 = pb.law.law.z0, w = pb.law.law.work;
  double l = std::sqrt(2 * pb.radius * z0);
  if (w > 0) l = std::min(l, pb.e_star * z0 * z0 / w);
  if (a > 0) l = std::min(l, pb.radius * z0 / a);
  return l;
}

double control_gap(const Problem& pb) { return pb.law.law.work > 0 ? 0.2 * pb.law.law.z0 : 0.0; }

namespace {

class Tracer {
 public:
  Tracer(const Problem& pb, const CurveSettings& set) : pb_(pb), set_(set) {}

  // Eq. 6.7.5: fine rings at the focus (edge or centre), graded to the cut-off radius.
  Grid grid_for(double a) const {
    double fine = gap_length(pb_, a) / set_.points_per_length;
    if (a > 0) fine = std::min(fine, a / 40);
    const double r_max = std::max({1.5 * a, 1.2 * r_cut_, a + 20 * fine});
    return graded_grid(a, fine, std::max(a / 20, fine), std::max(r_max / 25, fine), set_.growth, r_max);
  }

  // Solves at control value `v` (the radius rho where g = g* in contact, g(0) before; Eq. 6.7.4),
  // growing the grid until it holds the cut-off.
  bool attempt(double v, bool contact, const Equilibrium& prev, double approach_guess, Equilibrium& out) {
    const double rho = contact ? v : 0.0;
    const double stretch = contact && prev.control_radius > 0 ? prev.control_radius / rho : 1.0;
    for (int tries = 0; tries < 6; ++tries) {
      const Grid g = grid_for(rho);
      if (!solve_equilibrium(pb_, g, rho, contact ? control_gap(pb_) : v, interpolate_gaps(prev, g.points, stretch),
                             approach_guess, out))
        return false;
      if (holds_cutoff(out)) return true;
      r_cut_ *= 1.4;
    }
    return false;
  }

  void set_cut_radius(double r) { r_cut_ = r; }
  const Problem& problem() const { return pb_; }

 private:
  // The last ring must lie beyond the cut-off (zero traction); r_cut_ becomes the last ring inside it.
  bool holds_cutoff(const Equilibrium& s) {
    if (pb_.law.law.work == 0) return true;
    const double gc = pb_.law.law.capture_gap();
    if (s.gap.back() <= gc) return false;
    std::size_t k = s.gap.size();
    while (k > 0 && s.gap[k - 1] > gc) --k;
    r_cut_ = k > 0 ? s.grid.edges[k] : s.grid.edges[1];
    return true;
  }

  const Problem& pb_;
  const CurveSettings& set_;
  double r_cut_ = 0;
};

// The contact radius: the outermost radius where g <= g_j, the in-contact gap of the FE
// (`junction gap tolerance`, docs/theory.md 7.2 and 6.7.6), by bisection between grid points.
double radius_where(const Problem& pb, const Equilibrium& s, double gj) {
  std::size_t k = s.gap.size();
  while (k > 0 && s.gap[k - 1] > gj) --k;
  if (k == 0) return gap_at(pb, s, 0.0) <= gj ? s.grid.points[0] : 0.0;
  if (k == s.gap.size()) return s.grid.edges.back();
  double lo = s.grid.points[k - 1], hi = s.grid.points[k];
  for (int i = 0; i < 50 && hi - lo > 1e-9 * hi; ++i) (gap_at(pb, s, 0.5 * (lo + hi)) <= gj ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

// The edge of the hard contact: the penalty pressure q = -k g > 0 of the last two rings that carry it,
// q^2 extrapolated linearly in r to zero (exact for an elliptic edge, as the FE's pressure-fit radius);
// clamped to the next ring. 0 when no ring penetrates.
double compressive_radius_of(const Equilibrium& s) {
  std::size_t k = s.gap.size();
  while (k > 0 && !(s.gap[k - 1] < 0)) --k;
  if (k == 0) return 0.0;
  const auto& r = s.grid.points;
  const double q1 = s.gap[k - 1] * s.gap[k - 1];
  if (k == 1 || k == s.gap.size()) return s.grid.edges[k];
  const double q0 = s.gap[k - 2] * s.gap[k - 2];
  if (!(q0 > q1)) return s.grid.edges[k];
  return std::min(r[k - 1] + q1 * (r[k - 1] - r[k - 2]) / (q0 - q1), r[k]);
}

double contact_radius_of(const Problem& pb, const Equilibrium& s) {
  if (pb.law.law.work == 0 && pb.contact_gap == 0) return s.control_radius;  // g* = 0 = g_j: the control is the edge
  return radius_where(pb, s, pb.contact_gap);
}

CurvePoint point_of(const Problem& pb, const Equilibrium& s, bool contact) {
  CurvePoint p;
  p.branch = contact ? 1 : 0;
  p.parameter = contact ? s.control_radius : control_gap(pb) - s.central_gap;
  p.approach = s.approach;
  p.load = s.load;
  p.contact_radius = contact_radius_of(pb, s);
  p.bonded_radius = contact ? s.control_radius : 0.0;
  p.compressive_radius = pb.law.law.work == 0 ? p.contact_radius : compressive_radius_of(s);
  p.zone_radius = pb.law.law.work > 0 ? radius_where(pb, s, pb.law.law.z0) : p.contact_radius;
  p.central_gap = s.central_gap;
  p.min_gap = *std::min_element(s.gap.begin(), s.gap.end());
  p.rings = static_cast<int>(s.gap.size());
  return p;
}

double extrapolated_approach(const std::vector<CurvePoint>& pts, double s, double fallback) {
  const std::size_t n = pts.size();
  if (n == 0) return fallback;
  if (n < 2 || pts[n - 1].parameter == pts[n - 2].parameter) return pts.back().approach;
  const auto& p = pts[n - 1];
  const auto& q = pts[n - 2];
  return p.approach + (p.approach - q.approach) / (p.parameter - q.parameter) * (s - p.parameter);
}

[[noreturn]] void fail(const char* where, double v) {
  throw solver::NumericalFailure(std::string("tribex adhesion-curve: no equilibrium found ") + where + " " +
                                 std::to_string(v * 1e9) + " nm even with the step cut 2^30 times (try a finer --resolution)");
}

// A step is kept when Newton converged and the curve moved by at most max_load_step (in pi W_c R, or
// in max_load when W = 0) and 0.1 z0 in delta (docs/theory.md 6.7.4).
bool small_step(const Problem& pb, const CurveSettings& set, const Curve& c, const Equilibrium& next) {
  if (c.points.empty()) return true;
  const auto& p = c.points.back();
  const double wc = pb.law.captured_work();
  const double load_scale = wc > 0 ? M_PI * wc * pb.radius : set.max_load;
  if (std::abs(next.load - p.load) > set.max_load_step * load_scale) return false;
  if (wc == 0) return true;
  const double k = 4 * pb.e_star / 3, approach_scale = std::cbrt(M_PI * M_PI * wc * wc * pb.radius / (k * k));
  return std::abs(next.approach - p.approach) <= std::max(0.1 * pb.law.law.z0, 0.03 * approach_scale);
}

// One branch in its increasing parameter s (g* - g(0) before contact, rho after) from the last point
// through each target: the step grows by 1.5 after a kept step and halves after a rejected one.
void follow(Tracer& tr, const CurveSettings& set, Curve& c, std::vector<Equilibrium>& states, Equilibrium& prev, bool contact, const std::vector<double>& targets) {
  const Problem& pb = tr.problem();
  const double gs = control_gap(pb);
  auto param = [&](double v) { return contact ? v : gs - v; };
  auto value = [&](double s) { return contact ? s : gs - s; };
  double last = param(contact ? prev.control_radius : prev.central_gap);
  for (double target : targets) {
    double h = param(target) - last;
    int cuts = 0;
    while (last < param(target)) {
      const double s = std::min(last + h, param(target));
      Equilibrium next;
      if (tr.attempt(value(s), contact, prev, extrapolated_approach(c.points, s, prev.approach), next) &&
          small_step(pb, set, c, next)) {
        prev = next;
        states.push_back(next);
        c.points.push_back(point_of(pb, next, contact));
        c.max_rings = std::max(c.max_rings, c.points.back().rings);
        last = s;
        h *= 1.5;
        cuts = 0;
        continue;
      }
      if (++cuts > 30) fail(contact ? "at control radius" : "at central gap", value(s));
      h *= 0.5;
    }
  }
}

// Golden-section search of y(s) (load or approach, sign +1 for a minimum, -1 for a maximum) on
// [s_{k-1}, s_{k+1}] with a solve at every trial parameter, from the traced state k (docs/theory.md 6.7.7):
// exact to the solver's tolerance at smooth extrema and at kinks (the contact onset) alike.
Marker refine(Tracer& tr, const std::vector<Equilibrium>& states, const Curve& c, std::size_t k, bool of_load, double sign) {
  const Problem& pb = tr.problem();
  const double gs = control_gap(pb);
  const auto& p = c.points;
  CurvePoint best = p[k];
  auto y = [&](const CurvePoint& q) { return sign * (of_load ? q.load : q.approach); };
  auto eval = [&](double s) {
    const bool contact = s > 0;
    Equilibrium e;
    const std::size_t from = contact == (p[k].branch == 1) ? k : (contact ? k + 1 : k - 1);
    if (!tr.attempt(contact ? s : gs - s, contact, states[from], states[from].approach, e)) return std::numeric_limits<double>::infinity();
    const CurvePoint q = point_of(pb, e, contact);
    if (y(q) < y(best)) best = q;
    return y(q);
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double lo = p[k - 1].parameter, hi = p[k + 1].parameter;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = eval(x1), f2 = eval(x2);
  for (int i = 0; i < 30; ++i) {
    if (f1 <= f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = eval(x1); }
    else { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = eval(x2); }
  }
  return {true, best.approach, best.load, best.contact_radius, best.compressive_radius, best.bonded_radius, best.zone_radius};
}

}  // namespace

MarkerIndices find_markers(const Curve& c) {
  MarkerIndices m;
  const auto& p = c.points;
  const std::size_t n = p.size();
  if (n < 3) return m;
  for (std::size_t i = 1; i < n; ++i)
    if (p[i].load < p[m.pull_off].load) m.pull_off = i;
  for (std::size_t k = 1; k + 1 < n; ++k)  // approach: delta grows until the first local maximum
    if (p[k + 1].approach < p[k].approach) {
      if (p[k].approach >= p[k - 1].approach) m.jump_in = k;
      break;
    }
  for (std::size_t k = n - 2; k >= 1; --k)  // withdrawal from the largest load: delta falls to a local minimum
    if (p[k - 1].approach > p[k].approach) {
      if (p[k].approach <= p[k + 1].approach) m.jump_out = k;
      break;
    }
  return m;
}

Curve trace_curve(const Problem& pb, const CurveSettings& set) {
  Curve c;
  Tracer tr(pb, set);
  std::vector<Equilibrium> states;
  const double gc = pb.law.law.capture_gap();
  const bool adhesive = pb.law.law.work > 0;
  Equilibrium prev;
  prev.grid = graded_grid(0, gap_length(pb, 0) / set.points_per_length, 1, gc, set.growth, std::sqrt(2 * pb.radius * gc));
  for (double r : prev.grid.points) prev.gap.push_back((adhesive ? gc : 0.0) + r * r / (2 * pb.radius));
  prev.approach = adhesive ? -gc : 0.0;
  prev.central_gap = adhesive ? gc : 0.0;
  tr.set_cut_radius(prev.grid.edges.back());
  if (adhesive) {
    std::vector<double> g0;
    const double gs = control_gap(pb);
    for (int k = 0; k <= set.gap_steps; ++k) g0.push_back(gs + (gc - gs) * std::pow(1.0 - static_cast<double>(k) / set.gap_steps, 2));
    follow(tr, set, c, states, prev, false, g0);
  }
  double a = 0.05 * gap_length(pb, 0);
  for (int k = 0; k < 100000; ++k) {
    follow(tr, set, c, states, prev, true, {a});
    if (c.points.back().load > set.max_load) break;
    a *= 1 + set.radius_step;
  }
  const MarkerIndices m = find_markers(c);
  const std::size_t last = c.points.size() - 1;
  auto at = [&](std::size_t k) {
    const auto& q = c.points[k];
    return Marker{true, q.approach, q.load, q.contact_radius, q.compressive_radius, q.bonded_radius, q.zone_radius};
  };
  c.pull_off = m.pull_off > 0 && m.pull_off < last ? refine(tr, states, c, m.pull_off, true, 1.0) : at(m.pull_off);
  if (m.jump_in) c.jump_in = refine(tr, states, c, *m.jump_in, false, -1.0);
  if (m.jump_out) c.jump_out = refine(tr, states, c, *m.jump_out, false, 1.0);
  return c;
}

}  // namespace tribex::adhesion
