// SPDX-License-Identifier: MIT
// Frictionless axisymmetric contact of an elastic sphere (or a rigid flat punch) on a layer stack:
// the Abel-form integral equation of Sneddon type (Perriot & Barthel 2004; docs/theory.md 11.4.2)
//   (2/E_eff) g(x) + int_0^a g(t) B(x, t) dt = theta(x),  0 <= x <= a,
//   B(x, t) = (4/pi) int_0^inf [C(xi) - 1/E*_top] cos(xi x) cos(xi t) dxi,
// with 1/E_eff = 1/E*_indenter + 1/E*_top, theta = delta - x^2/R (sphere) or delta (flat punch),
// load P = 4 int_0^a g dt and pressure p(r) = -(2/pi) int_r^a g'(t)/sqrt(t^2 - r^2) dt (+ the edge term
// of a punch). A Fredholm equation of the second kind, solved by Nystrom's method on Gauss-Legendre
// nodes; the smooth edge g(a) = 0 fixes delta for the sphere.
#pragma once

#include <vector>

#include "contact/rough/gauss_legendre.hpp"
#include "tools/layered/stack.hpp"

namespace tribex::layered {

/// Accuracy knobs (docs/theory.md 11.4.3; defaults converge f to about 1e-12, tests/layered).
struct Settings {
  int nodes = 24;              // Nystrom (Gauss-Legendre) nodes on [0, a], at least
  double nodes_per_thickness = 6;  // ... and at least this many per top-layer thickness h_top (at most 1000)
  int hankel_per_panel = 16;   // Gauss-Legendre points per panel of the xi integral
  double hankel_extent = 40;   // xi_max = extent / h_top: C - 1/E*_top ~ e^{-2 xi h_top} is below 1e-30 there
  double panels_per_radius = 1.0;  // xi panel width min(1/H, 1/(panels_per_radius a_grid)), a_grid = 2a: a third of a period of cos(2 a xi)
};

struct SphereSolution {
  double radius = 0;   // contact radius a (m)
  double approach = 0; // delta (m): indenter plus layered body
  double load = 0;     // P (N)
  gw::QuadratureRule nodes;          // Nystrom nodes t_j on [0, a]
  std::vector<double> g;  // g(t_j) (N/m)
};

class Contact {
 public:
  /// `indenter`: E = infinity for a rigid one. `sphere_radius` R (m).
  Contact(Stack stack, Elastic indenter, double sphere_radius, Settings settings = {});

  /// The sphere pressed to contact radius a (smooth edge).
  SphereSolution sphere(double a);
  /// The sphere at load P (N), or at approach delta (m): Newton-secant in ln a from `guess` (m).
  SphereSolution sphere_at_load(double load, double guess);
  SphereSolution sphere_at_approach(double approach, double guess);
  /// Load on a flat punch of radius a pressed by delta = 1 m: the punch stiffness dP/ddelta (N/m).
  double flat_punch_stiffness(double a);
  /// p(r) (Pa) of a sphere solution at each radius r < a.
  std::vector<double> pressure(const SphereSolution& s, const std::vector<double>& r);

  /// 1/E_eff = 1/E*_indenter + 1/E*_top (Pa): the Hertz modulus against the top layer.
  double effective_modulus() const { return e_eff_; }
  std::size_t hankel_points() const { return xi_.size(); }
  double sphere_radius() const { return r_; }

 private:
  void ensure_grid(double a);
  int node_count(double a) const;
  /// Nystrom operator (E_eff/2) B(x_i, t_j) w_j on the nodes of [0, a], and its row at x = a.
  void operator_on(const gw::QuadratureRule& nodes, double a, std::vector<double>& matrix, std::vector<double>& edge_row) const;
  SphereSolution sphere_at(double target, bool by_load, double guess);

  Stack stack_;
  double inv_e_indenter_, r_, e_eff_;
  Settings settings_;
  double grid_radius_ = 0;
  std::vector<double> xi_, weight_;  // xi_q and (4/pi) W_q (C(xi_q) - 1/E*_top)
};

}  // namespace tribex::layered
