// SPDX-License-Identifier: MIT
// Closest-point projection of a point onto a bilinear quadrilateral face (docs/theory.md 5.1, local
// phase): x(xi, eta) = sum_a N_a x_a, N_a = (1 + xi_a xi)(1 + eta_a eta)/4, nodes (--), (+-), (++), (-+)
// counter-clockwise seen from outside. Newton on r = (x(xi,eta) - p) . x_{,xi|eta} = 0 from the
// centre; if the Newton point falls outside the face (beyond the tolerance) the closest point on
// the boundary edges is used instead (edge and vertex fallback).
#pragma once

namespace tribex::contact {

struct Projection {
  double xi = 0.0, eta = 0.0;  // parametric coordinates of the closest point, clipped to [-1, 1]
  double point[3] = {0, 0, 0}; // closest point on the face
  double normal[3] = {0, 0, 1};  // unit outward normal of the face at (xi, eta)
  double gap = 0.0;             // signed: (p - point) . normal, > 0 outside, < 0 penetrated
  double distance = 0.0;        // |p - point|
  bool interior = false;        // the Newton point lies inside the face (|xi|, |eta| <= 1 + tol)
  double shape[4] = {0, 0, 0, 0};  // N_a(xi, eta) at the closest point
};

/// The face map at (xi, eta): position and tangents x_{,xi}, x_{,eta} of the face X [4][3].
struct FaceMap {
  double x[3], xs[3], xe[3];
};
FaceMap face_map(const double X[12], double xi, double eta);

/// How far outside the parametric square a Newton point still counts as over the face.
inline constexpr double interior_tolerance = 1e-3;

/// `x` holds the 4 face nodes [4][3]; `p` the point. `tolerance` widens the accepted parametric
/// square (|xi|, |eta| <= 1 + tolerance) before falling back to the edges.
Projection project_onto_quad(const double x[12], const double p[3], double tolerance = interior_tolerance);

/// The edge and vertex fallback of project_onto_quad alone: the closest point of the face's boundary
/// (`interior` false). project_onto_quad returns exactly this whenever its Newton point is not over
/// the face, so a caller that has proved it cannot be (FaceBound::may_project_inside) calls this
/// instead and gets the same bits for a fraction of the work.
Projection project_onto_quad_boundary(const double x[12], const double p[3]);

}  // namespace tribex::contact
