// SPDX-License-Identifier: MIT
// docs/theory.md 6.7.2-6.7.3: discretisation and Newton solve of the sphere-flat equilibrium.
#include "tools/adhesion/solver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "tools/adhesion/kernel.hpp"

namespace tribex::adhesion {
namespace {

std::vector<double> steps_away(double length, double fine, double coarse, double growth) {
  std::vector<double> d{0.0};
  double h = fine;
  while (d.back() < length) {
    d.push_back(d.back() + h);
    h = std::min(h * growth, coarse);
  }
  // Land exactly on `length`: drop a last point that would leave a sliver under half a step.
  if (d.size() > 2 && length - d[d.size() - 2] < 0.5 * (d[d.size() - 2] - d[d.size() - 3])) d.erase(d.end() - 2);
  d.back() = length;
  return d;
}

double ring_area(const Grid& g, std::size_t j) { return M_PI * (g.edges[j + 1] * g.edges[j + 1] - g.edges[j] * g.edges[j]); }

}  // namespace

Grid graded_grid(double focus, double fine, double coarse_in, double coarse_out, double growth, double r_max) {
  Grid g;
  if (focus > 0) {
    const auto in = steps_away(focus, fine, std::max(coarse_in, fine), growth);
    for (auto it = in.rbegin(); it != in.rend(); ++it) g.edges.push_back(focus - *it);
    g.edges.front() = 0.0;
  } else {
    g.edges.push_back(0.0);
  }
  const auto out = steps_away(r_max - focus, fine, std::max(coarse_out, fine), growth);
  for (std::size_t k = 1; k < out.size(); ++k) g.edges.push_back(focus + out[k]);
  for (std::size_t j = 0; j + 1 < g.edges.size(); ++j) g.points.push_back(0.5 * (g.edges[j] + g.edges[j + 1]));
  return g;
}

double gap_at(const Problem& pb, const Equilibrium& s, double r) {
  const auto c = ring_influence({r}, s.grid.edges, pb.e_star);
  double g = -s.approach + r * r / (2 * pb.radius);
  for (std::size_t j = 0; j < s.gap.size(); ++j) g += c[j] * pb.law.pressure(s.gap[j]);
  return g;
}

std::vector<double> interpolate_gaps(const Equilibrium& s, const std::vector<double>& points, double stretch) {
  std::vector<double> out;
  const auto& x = s.grid.points;
  for (double r : points) {
    const double q = r * stretch;
    const auto it = std::lower_bound(x.begin(), x.end(), q);
    if (it == x.begin()) { out.push_back(s.gap.front()); continue; }
    if (it == x.end()) {  // beyond the old grid: continue the last segment's slope
      const std::size_t k = x.size() - 1;
      const double slope = k > 0 ? (s.gap[k] - s.gap[k - 1]) / (x[k] - x[k - 1]) : 0.0;
      out.push_back(s.gap[k] + slope * (q - x[k]));
      continue;
    }
    const std::size_t k = static_cast<std::size_t>(it - x.begin());
    const double t = (q - x[k - 1]) / (x[k] - x[k - 1]);
    out.push_back((1 - t) * s.gap[k - 1] + t * s.gap[k]);
  }
  return out;
}

// Newton on F_i = g_i + delta - r_i^2/(2R) - sum_j C_ij p(g_j) (i < n) and
// F_n = -delta + r_c^2/(2R) + sum_j C_cj p(g_j) - target (Eq. 6.7.4), with a backtracking line search.
bool solve_equilibrium(const Problem& pb, const Grid& grid, double control_radius, double target,
                       std::vector<double> guess, double approach_guess, Equilibrium& out) {
  const std::size_t n = grid.points.size();
  const auto c = ring_influence(grid.points, grid.edges, pb.e_star);
  const auto cc = ring_influence({control_radius}, grid.edges, pb.e_star);
  const double z0 = pb.law.law.z0;
  Eigen::VectorXd x(n + 1);
  for (std::size_t i = 0; i < n; ++i) x[i] = guess[i];
  x[n] = approach_guess;
  auto residual = [&](const Eigen::VectorXd& v, Eigen::VectorXd& f) {
    std::vector<double> p(n);
    for (std::size_t j = 0; j < n; ++j) p[j] = pb.law.pressure(v[j]);
    f.resize(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
      double u = 0;
      for (std::size_t j = 0; j < n; ++j) u += c[i * n + j] * p[j];
      f[i] = v[i] + v[n] - grid.points[i] * grid.points[i] / (2 * pb.radius) - u;
    }
    double u = 0;
    for (std::size_t j = 0; j < n; ++j) u += cc[j] * p[j];
    f[n] = -v[n] + control_radius * control_radius / (2 * pb.radius) + u - target;
  };
  Eigen::VectorXd f, trial_f;
  residual(x, f);
  Eigen::MatrixXd jac(n + 1, n + 1);
  const double tolerance = 1e-10 * z0;
  for (int it = 0; it < 60; ++it) {
    if (f.lpNorm<Eigen::Infinity>() < tolerance) {
      out.grid = grid;
      out.gap.assign(x.data(), x.data() + n);
      out.approach = x[n];
      out.control_radius = control_radius;
      out.iterations = it;
      out.load = 0;
      for (std::size_t j = 0; j < n; ++j) out.load += pb.law.pressure(out.gap[j]) * ring_area(grid, j);
      out.central_gap = control_radius == 0 ? target : gap_at(pb, out, 0.0);
      return true;
    }
    for (std::size_t j = 0; j < n; ++j) {
      const double dp = pb.law.slope(x[j]);
      for (std::size_t i = 0; i < n; ++i) jac(i, j) = -c[i * n + j] * dp;
      jac(j, j) += 1.0;
      jac(n, j) = cc[j] * dp;
    }
    for (std::size_t i = 0; i < n; ++i) jac(i, n) = 1.0;
    jac(n, n) = -1.0;
    const Eigen::VectorXd dx = jac.partialPivLu().solve(-f);
    if (!dx.allFinite()) return false;
    double step = 1.0, norm = f.norm();
    bool accepted = false;
    for (int k = 0; k < 30; ++k, step *= 0.5) {
      const Eigen::VectorXd trial = x + step * dx;
      residual(trial, trial_f);
      if (trial_f.norm() < (1 - 1e-4 * step) * norm || trial_f.lpNorm<Eigen::Infinity>() < tolerance) {
        x = trial;
        f = trial_f;
        accepted = true;
        break;
      }
    }
    if (!accepted) return false;
  }
  return false;
}

}  // namespace tribex::adhesion
