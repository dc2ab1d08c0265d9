// SPDX-License-Identifier: MIT
// One equilibrium of the Lennard-Jones sphere-flat reference (docs/theory.md 6.7): the gap
//   g(r) = -delta + r^2/(2R) + sum_j C(r, ring j) p(g_j)                  (Eq. 6.7.2)
// collocated at the ring midpoints, closed by one control equation g(r_c) = g_target (Eq. 6.7.4): the
// central gap (r_c = 0) first, then the radius rho where g = g* (r_c = rho, g_target = g*).
// Unknowns: the gaps at the midpoints and delta; Newton with a backtracking line search.
#pragma once

#include <vector>

#include "tools/adhesion/law.hpp"

namespace tribex::adhesion {

struct Problem {
  double radius = 0;  // R, m (paraboloid r^2/(2R))
  double e_star = 0;  // composite modulus E*, Pa
  GapLaw law;
  double contact_gap = 0;  // g_j, m: in contact where g <= g_j (the FE's `junction gap tolerance`, default 0.05 z0)
};

/// The sphere radius at Tabor parameter mu: mu_T = (R W^2 / (E*^2 z0^3))^(1/3) (docs/theory.md 6.7)
/// solved for R, m.
inline double radius_at_tabor(double mu, double e_star, double work, double z0) {
  return mu * mu * mu * e_star * e_star * z0 * z0 * z0 / (work * work);
}

/// The reference problem the tests and the regression table use at Tabor parameter mu: the law's default
/// cut-off 20 z0, a hard-contact penalty 1000 E*/z0, in contact where g <= 0.05 z0.
inline Problem problem_at_tabor(double mu, double e_star, double work, double z0) {
  Problem pb;
  pb.e_star = e_star;
  pb.law.law = {work, z0, 20 * z0};
  pb.law.penalty = 1000 * e_star / z0;
  pb.contact_gap = 0.05 * z0;
  pb.radius = radius_at_tabor(mu, e_star, work, z0);
  return pb;
}

/// Ring edges (0 = edges[0] < ... < edges.back() = r_max) and collocation midpoints.
struct Grid {
  std::vector<double> edges, points;
};

/// Edges graded geometrically (ratio `growth`) away from `focus` (rho; 0 while the central gap is the control):
/// spacing `fine` at the focus, at most `coarse_in` inside it and `coarse_out` outside, up to r_max.
Grid graded_grid(double focus, double fine, double coarse_in, double coarse_out, double growth, double r_max);

struct Equilibrium {
  Grid grid;
  std::vector<double> gap;    // at grid.points, m
  double approach = 0;        // delta, m (0 = the undeformed surfaces at touching, h = z0)
  double control_radius = 0;  // r_c, m (rho on branch 1, 0 while the central gap is the control)
  double load = 0;            // P = 2 pi int p r dr, N, compressive positive
  double central_gap = 0;     // g(0), m
  int iterations = 0;
};

/// Gap at radius r of a solved state (Eq. 6.7.2 evaluated off the collocation points).
double gap_at(const Problem& pb, const Equilibrium& s, double r);

/// Solves for the gaps and delta with g(control_radius) = target on `grid`, from `guess` (gaps at the
/// grid points) and `approach_guess`. Returns false when Newton does not converge.
bool solve_equilibrium(const Problem& pb, const Grid& grid, double control_radius, double target,
                       std::vector<double> guess, double approach_guess, Equilibrium& out);

/// Gaps of `s` interpolated (linearly, in r scaled by `stretch`) at new points: the predictor.
std::vector<double> interpolate_gaps(const Equilibrium& s, const std::vector<double>& points, double stretch);

}  // namespace tribex::adhesion
