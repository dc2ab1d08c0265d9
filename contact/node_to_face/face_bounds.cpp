// SPDX-License-Identifier: MIT
#include "contact/node_to_face/face_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "contact/geometry/quad_projection.hpp"

namespace tribex::contact {
namespace {

constexpr double xi_a[4] = {-1, 1, 1, -1};
constexpr double eta_a[4] = {-1, -1, 1, 1};

// x_{,xi} x x_{,eta} at (s, t) (the face map of quad_projection.hpp), not normalised.
void normal_at(const double X[12], double s, double t, double n[3]) {
  const FaceMap m = face_map(X, s, t);
  n[0] = m.xs[1] * m.xe[2] - m.xs[2] * m.xe[1];
  n[1] = m.xs[2] * m.xe[0] - m.xs[0] * m.xe[2];
  n[2] = m.xs[0] * m.xe[1] - m.xs[1] * m.xe[0];
}

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

// Why the test is safe. project_onto_quad reports `interior` only where its Newton iteration has
// converged at (s, t), |s|, |t| <= 1 + tol, to a stationary point of |x(s, t) - p|: p - x = g n(s, t).
// With c the centre, d = p - c and n0 the centre normal, the part of d across n0 is then at most
// |x - c| + |g| sin(angle(n(s, t), n0)), and |g| <= |d| + |x - c|.
//  - x - c = sum_a N_a(s, t) (X_a - c) with sum_a |N_a| = max(1, |s|) max(1, |t|) <= (1 + tol)^2, so
//    |x - c| <= (1 + tol)^2 max_a |X_a - c| = reach.
//  - x_{,xi} is linear in t and x_{,eta} in s, so their cross product is bilinear in (s, t) and equals
//    sum_a N_a(s, t) M_a, M_a its values at the corners. With weights of negative sum at most
//    nu = ((1 + tol)^2 - 1) / 2: its part along n0 is at least (1 + nu) min_a M_a.n0 - nu max_a M_a.n0,
//    its part across n0 at most (1 + 2 nu) max_a |M_a across n0|; their ratio bounds the sine (spread).
// A point p whose part across n0 exceeds reach + (|d| + reach) spread (plus a relative slack of 1e-6
// for the Newton tolerance and round-off) therefore has no such stationary point.
FaceBound bound_face(const double X[12], double tolerance) {
  FaceBound b{};
  for (int i = 0; i < 3; ++i) {
    b.lo[i] = std::min(std::min(X[i], X[3 + i]), std::min(X[6 + i], X[9 + i]));
    b.hi[i] = std::max(std::max(X[i], X[3 + i]), std::max(X[6 + i], X[9 + i]));
    b.centre[i] = 0.25 * (X[i] + X[3 + i] + X[6 + i] + X[9 + i]);
  }
  double n0[3];
  normal_at(X, 0.0, 0.0, n0);
  const double len = std::sqrt(dot(n0, n0));
  double r2 = 0.0;
  for (int a = 0; a < 4; ++a) {
    double d[3];
    for (int i = 0; i < 3; ++i) d[i] = X[3 * a + i] - b.centre[i];
    r2 = std::max(r2, dot(d, d));
  }
  const double band = (1 + tolerance) * (1 + tolerance);
  b.reach = band * std::sqrt(r2);
  b.tested = false;
  if (!(len > 0.0)) return b;
  for (int i = 0; i < 3; ++i) b.normal[i] = n0[i] / len;
  double along_min = INFINITY, along_max = 0.0, across_max = 0.0;
  for (int a = 0; a < 4; ++a) {
    double m[3];
    normal_at(X, xi_a[a], eta_a[a], m);
    const double along = dot(m, b.normal);
    double across[3];
    for (int i = 0; i < 3; ++i) across[i] = m[i] - along * b.normal[i];
    along_min = std::min(along_min, along);
    along_max = std::max(along_max, along);
    across_max = std::max(across_max, std::sqrt(dot(across, across)));
  }
  const double nu = 0.5 * (band - 1.0);
  const double denominator = (1 + nu) * along_min - nu * along_max;
  if (!(denominator > 0.0)) return b;
  b.spread = (1 + 2 * nu) * across_max / denominator;
  b.tested = b.spread < 0.5;  // beyond 30 degrees of warp the bound rules out little: always project
  return b;
}

bool FaceBound::may_project_inside(const double* p) const {
  if (!tested) return true;
  double d[3];
  for (int i = 0; i < 3; ++i) d[i] = p[i] - centre[i];
  const double along = dot(d, normal);
  double across[3];
  for (int i = 0; i < 3; ++i) across[i] = d[i] - along * normal[i];
  const double distance = std::sqrt(dot(d, d));
  const double limit = reach + (distance + reach) * spread + 1e-6 * (distance + reach);
  return dot(across, across) <= limit * limit;
}

double FaceBound::box_distance(const double* p) const {
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double out = std::max(std::max(lo[i] - p[i], p[i] - hi[i]), 0.0);
    d2 += out * out;
  }
  return std::sqrt(d2);
}

void FaceBounds::resize(int face_count) {
  bound_.resize(face_count);
  stamp_.assign(face_count, 0);
  epoch_ = 1;
}

void FaceBounds::next_step() {
  if (++epoch_ == 0) {  // wrapped (after 2^32 steps): stamps of 0 would look current
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    epoch_ = 1;
  }
}

const FaceBound& FaceBounds::of(const double* x, const ContactSurface& surface, int face) {
  if (stamp_[face] != epoch_) {
    double X[12];
    surface.face_coordinates(x, face, X);
    bound_[face] = bound_face(X, interior_tolerance);
    stamp_[face] = epoch_;
  }
  return bound_[face];
}

}  // namespace tribex::contact
