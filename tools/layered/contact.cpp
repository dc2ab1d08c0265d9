// SPDX-License-Identifier: MIT
// docs/theory.md 11.4.2-11.4.3.
#include "tools/layered/contact.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "solver/errors.hpp"
#include "tools/layered/kernel.hpp"

namespace tribex::layered {

Contact::Contact(Stack stack, Elastic indenter, double sphere_radius, Settings settings)
    : stack_(std::move(stack)), r_(sphere_radius), settings_(settings) {
  validate(stack_);
  inv_e_indenter_ = std::isinf(indenter.youngs) ? 0.0 : 1.0 / indenter.plane_strain();
  e_eff_ = 1.0 / (inv_e_indenter_ + 1.0 / stack_.top().plane_strain());
}

void Contact::ensure_grid(double a) {
  if (a <= grid_radius_) return;
  grid_radius_ = 2.0 * a;  // room for the loads that follow
  xi_.clear();
  weight_.clear();
  if (stack_.layers.empty()) return;  // homogeneous half-space: B = 0
  const double h_top = stack_.layers.front().thickness;
  const double xi_max = settings_.hankel_extent / h_top;
  // Panels narrower than both the stack's depth scale 1/H (C varies on it at small xi) and the
  // oscillation of cos(xi x) cos(xi t), x + t <= 2a (period pi/a).
  const double width = std::min(1.0 / stack_.total_thickness(), 1.0 / (settings_.panels_per_radius * grid_radius_));
  const int panels = std::max(1, static_cast<int>(std::ceil(xi_max / width)));
  const gw::QuadratureRule rule = gw::composite_gauss_legendre_rule(panels, settings_.hankel_per_panel, 0.0, xi_max);
  const double c_top = 1.0 / stack_.top().plane_strain();
  for (std::size_t q = 0; q < rule.x.size(); ++q) {
    const double dc = surface_compliance(stack_, rule.x[q]) - c_top;
    if (dc == 0.0) continue;
    xi_.push_back(rule.x[q]);
    weight_.push_back(4.0 / std::numbers::pi * rule.w[q] * dc);
  }
}

void Contact::operator_on(const gw::QuadratureRule& nodes, double a, std::vector<double>& matrix, std::vector<double>& edge_row) const {
  const std::size_t n = nodes.x.size();
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd edge = Eigen::VectorXd::Zero(n);
  const std::size_t block = 2048;  // xi points per block: B = Cx^T diag(weight) Cx, Cx_qj = cos(xi_q t_j)
  for (std::size_t q0 = 0; q0 < xi_.size(); q0 += block) {
    const std::size_t m = std::min(block, xi_.size() - q0);
    Eigen::MatrixXd cx(m, n);
    Eigen::VectorXd wa(m);
    for (std::size_t q = 0; q < m; ++q) {
      for (std::size_t j = 0; j < n; ++j) cx(q, j) = std::cos(xi_[q0 + q] * nodes.x[j]);
      wa(q) = weight_[q0 + q] * std::cos(xi_[q0 + q] * a);
    }
    Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(weight_.data() + q0, m);
    b.noalias() += cx.transpose() * w.asDiagonal() * cx;
    edge.noalias() += cx.transpose() * wa;
  }
  matrix.assign(n * n, 0.0);
  edge_row.assign(n, 0.0);
  const double s = 0.5 * e_eff_;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) matrix[i * n + j] = s * b(i, j) * nodes.w[j];
    edge_row[i] = s * edge(i) * nodes.w[i];
  }
}

int Contact::node_count(double a) const {
  // B(x, t) has features of width h_top: a layer much thinner than the contact needs a/h_top nodes.
  if (stack_.layers.empty()) return settings_.nodes;
  const double per = settings_.nodes_per_thickness * a / stack_.layers.front().thickness;
  if (per > 1000)
    throw solver::NumericalFailure("layered contact: the top layer (h = " + std::to_string(stack_.layers.front().thickness * 1e9) +
                                   " nm) is too thin for a contact radius of " + std::to_string(a * 1e9) +
                                   " nm (a/h above 1000/nodes_per_thickness needs more than 1000 nodes); use smaller loads");
  return std::max(static_cast<int>(std::ceil(per)), settings_.nodes);
}

SphereSolution Contact::sphere(double a) {
  const int nodes = node_count(a);  // before the grid: a layer too thin fails at once, not after building it
  ensure_grid(a);
  SphereSolution s;
  s.radius = a;
  s.nodes = gw::gauss_legendre_rule(nodes, 0.0, a);
  const std::size_t n = s.nodes.x.size();
  std::vector<double> k, edge;
  operator_on(s.nodes, a, k, edge);
  // (g + K g) = (E_eff/2) theta: solve for theta = 1 (g1) and theta = -x^2/R (g2); g = delta g1 + g2.
  Eigen::MatrixXd m = Eigen::Map<const Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(k.data(), n, n);
  m += Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd rhs(n, 2);
  const double half = 0.5 * e_eff_;
  for (std::size_t i = 0; i < n; ++i) {
    rhs(i, 0) = half;
    rhs(i, 1) = -half * s.nodes.x[i] * s.nodes.x[i] / r_;
  }
  const Eigen::MatrixXd g = m.partialPivLu().solve(rhs);
  const Eigen::Map<const Eigen::VectorXd> e(edge.data(), n);
  // Nystrom interpolation to x = a: g(a) = (E_eff/2) theta(a) - sum_j (E_eff/2) B(a, t_j) w_j g_j.
  const double g1a = half - e.dot(g.col(0));
  const double g2a = -half * a * a / r_ - e.dot(g.col(1));
  s.approach = -g2a / g1a;
  s.g.resize(n);
  s.load = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.g[i] = s.approach * g(i, 0) + g(i, 1);
    s.load += 4.0 * s.nodes.w[i] * s.g[i];
  }
  return s;
}

double Contact::flat_punch_stiffness(double a) {
  const int count = node_count(a);  // before the grid, as in sphere()
  ensure_grid(a);
  const gw::QuadratureRule nodes = gw::gauss_legendre_rule(count, 0.0, a);
  const std::size_t n = nodes.x.size();
  std::vector<double> k, edge;
  operator_on(nodes, a, k, edge);
  Eigen::MatrixXd m = Eigen::Map<const Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(k.data(), n, n);
  m += Eigen::MatrixXd::Identity(n, n);
  const Eigen::VectorXd g = m.partialPivLu().solve(Eigen::VectorXd::Constant(n, 0.5 * e_eff_));
  double load = 0.0;
  for (std::size_t i = 0; i < n; ++i) load += 4.0 * nodes.w[i] * g(i);
  return load;  // delta = 1 m
}

SphereSolution Contact::sphere_at(double target, bool by_load, double guess) {
  // Newton-secant on F(ln a) = ln X(a) - ln X_target, X = P (slope about 3) or delta (about 2).
  double la = std::log(guess), slope = by_load ? 3.0 : 2.0;
  SphereSolution s = sphere(guess);
  double f = std::log(by_load ? s.load : s.approach) - std::log(target);
  for (int it = 0; it < 60; ++it) {
    if (std::abs(f) < 1e-14) return s;
    const double la_new = la - f / slope;
    SphereSolution s_new = sphere(std::exp(la_new));
    const double x = by_load ? s_new.load : s_new.approach;
    if (!(x > 0)) break;
    const double f_new = std::log(x) - std::log(target);
    if (la_new != la && f_new != f) slope = (f_new - f) / (la_new - la);
    la = la_new;
    f = f_new;
    s = std::move(s_new);
    if (!(slope > 0)) break;
  }
  throw solver::NumericalFailure(std::string("layered contact: no contact radius found for the ") +
                                 (by_load ? "load " : "approach ") + std::to_string(target) +
                                 " (load or approach not monotonic in a; check the stack)");
}

SphereSolution Contact::sphere_at_load(double load, double guess) { return sphere_at(load, true, guess); }
SphereSolution Contact::sphere_at_approach(double approach, double guess) { return sphere_at(approach, false, guess); }

std::vector<double> Contact::pressure(const SphereSolution& s, const std::vector<double>& radii) {
  // g'(x) = (E_eff/2) theta'(x) - sum_j (E_eff/2) dB/dx(x, t_j) w_j g_j, theta' = -2x/R;
  // p(r) = -(2/pi) int_0^sqrt(a^2 - r^2) g'(t)/t ds with t = sqrt(r^2 + s^2) (no edge term: g(a) = 0).
  const double half = 0.5 * e_eff_;
  std::vector<double> moment(xi_.size(), 0.0);  // sum_j cos(xi_q t_j) w_j g_j
  for (std::size_t q = 0; q < xi_.size(); ++q)
    for (std::size_t j = 0; j < s.g.size(); ++j) moment[q] += std::cos(xi_[q] * s.nodes.x[j]) * s.nodes.w[j] * s.g[j];
  auto dg = [&](double x) {
    double sum = 0.0;  // sum_j w_j g_j dB/dx(x, t_j)
    for (std::size_t q = 0; q < xi_.size(); ++q) sum -= weight_[q] * xi_[q] * std::sin(xi_[q] * x) * moment[q];
    return half * (-2.0 * x / r_) - half * sum;
  };
  std::vector<double> out;
  for (double r : radii) {
    if (r >= s.radius) {
      out.push_back(0.0);
      continue;
    }
    const gw::QuadratureRule rule = gw::gauss_legendre_rule(settings_.nodes, 0.0, std::sqrt(s.radius * s.radius - r * r));
    double integral = 0.0;
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
      const double t = std::sqrt(r * r + rule.x[i] * rule.x[i]);
      integral += rule.w[i] * dg(t) / t;
    }
    out.push_back(-2.0 / std::numbers::pi * integral);
  }
  return out;
}

}  // namespace tribex::layered
