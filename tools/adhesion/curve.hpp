// SPDX-License-Identifier: MIT
// The load-approach curve of the Lennard-Jones sphere-flat reference traced through both branches
// (docs/theory.md 6.7.4): first the control is the central gap g(0), stepped from the cut-off down to
// g* = 0.2 z0; then the radius rho where g = g*, stepped up to the largest load. Neither turns at the
// jump-in or the jump-out (the turning points of delta), so the path passes both; the pull-off under load
// control and the jumps under displacement control are read off the traced path and refined (6.7.7).
#pragma once

#include <optional>
#include <vector>

#include "tools/adhesion/solver.hpp"

namespace tribex::adhesion {

struct CurveSettings {
  double points_per_length = 8;  // ring spacing at the edge = (shortest gap length)/this (Eq. 6.7.5)
  double growth = 1.1;           // ratio of neighbouring ring widths away from the edge
  double radius_step = 0.03;     // relative step in rho between targets (steps adapt below it)
  int gap_steps = 60;            // targets of the central gap from g_c to g*
  double max_load = 0;           // N; the contact branch ends past it
  double max_load_step = 0.03;   // largest change of P/(pi W_c R) between traced points
};

struct CurvePoint {
  double parameter = 0;     // s = g* - g(0) before (branch 0), s = rho after (branch 1), m
  int branch = 0;           // 0: control g(0) > g*; 1: control rho, the radius where g = g*
  double approach = 0;      // delta, m
  double load = 0;          // P, N (compressive positive)
  double contact_radius = 0;// a, m: outermost radius with p >= 0 (g <= g_eq)
  double compressive_radius = 0;  // outermost radius where g <= 0 (the hard contact carries pressure), m
  double bonded_radius = 0; // rho, m: the radius where g = g* (0 while g(0) > g*)
  double zone_radius = 0;   // outermost radius where g = z0, m: the cohesive zone is a..zone_radius (docs/theory.md 6.7.6)
  double central_gap = 0;   // g(0), m
  double min_gap = 0;       // smallest gap on the grid, m (negative: penalty penetration)
  int rings = 0;
};

/// A point found between traced points by a parabola through three neighbours (in s).
struct Marker {
  bool found = false;
  double approach = 0, load = 0, contact_radius = 0, compressive_radius = 0, bonded_radius = 0, zone_radius = 0;
};

struct Curve {
  std::vector<CurvePoint> points;
  Marker pull_off;  // min P (load control); always found
  Marker jump_in;   // first local max of delta on approach (displacement control), if any
  Marker jump_out;  // first local min of delta on withdrawal from the largest load, if any
  int max_rings = 0;
};

/// Eq. 6.7.5: the gap rises by z0 over about min(E* z0^2/W, sqrt(2 R z0), R z0/a).
double gap_length(const Problem& pb, double a);

/// g*: the gap that defines the control radius rho on the contact branch (Eq. 6.7.4): 0.2 z0 (about
/// the separation of the peak attraction), 0 when W = 0.
double control_gap(const Problem& pb);

/// Traces the curve; throws solver::NumericalFailure when a step cannot be solved even when cut 2^30 times.
Curve trace_curve(const Problem& pb, const CurveSettings& set);

/// Where the extrema of a traced path lie (indices into points; refined by trace_curve).
struct MarkerIndices {
  std::size_t pull_off = 0;                  // the smallest load
  std::optional<std::size_t> jump_in, jump_out;  // first local max of delta forward, first local min backward
};
MarkerIndices find_markers(const Curve& c);

}  // namespace tribex::adhesion
