// SPDX-License-Identifier: MIT
#include "contact/geometry/quad_projection.hpp"

#include <algorithm>
#include <cmath>

namespace tribex::contact {
namespace {

constexpr double xi_a[4] = {-1, 1, 1, -1};
constexpr double eta_a[4] = {-1, -1, 1, 1};

void finish(const double X[12], const double p[3], double s, double t, Projection& out) {
  const FaceMap m = face_map(X, s, t);
  double n[3] = {m.xs[1] * m.xe[2] - m.xs[2] * m.xe[1], m.xs[2] * m.xe[0] - m.xs[0] * m.xe[2],
                 m.xs[0] * m.xe[1] - m.xs[1] * m.xe[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double d[3], dist2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    out.point[i] = m.x[i];
    out.normal[i] = len > 0 ? n[i] / len : 0.0;
    d[i] = p[i] - m.x[i];
    dist2 += d[i] * d[i];
  }
  out.xi = s;
  out.eta = t;
  out.distance = std::sqrt(dist2);
  out.gap = d[0] * out.normal[0] + d[1] * out.normal[1] + d[2] * out.normal[2];
  for (int a = 0; a < 4; ++a) out.shape[a] = 0.25 * (1 + xi_a[a] * s) * (1 + eta_a[a] * t);
}

// Closest point of p on the straight edge from parametric point (s0,t0) to (s1,t1); edges of a
// bilinear quad are straight lines between their end nodes.
void closest_on_edge(const double X[12], const double p[3], int a, int b, double& s, double& t, double& d2) {
  const double* xa = X + 3 * a;
  const double* xb = X + 3 * b;
  double e[3], w[3], ee = 0.0, we = 0.0;
  for (int i = 0; i < 3; ++i) {
    e[i] = xb[i] - xa[i];
    w[i] = p[i] - xa[i];
    ee += e[i] * e[i];
    we += w[i] * e[i];
  }
  const double r = ee > 0 ? std::clamp(we / ee, 0.0, 1.0) : 0.0;
  d2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double q = w[i] - r * e[i];
    d2 += q * q;
  }
  s = xi_a[a] + r * (xi_a[b] - xi_a[a]);
  t = eta_a[a] + r * (eta_a[b] - eta_a[a]);
}

}  // namespace

FaceMap face_map(const double X[12], double s, double t) {
  FaceMap m{};
  for (int a = 0; a < 4; ++a) {
    const double N = 0.25 * (1 + xi_a[a] * s) * (1 + eta_a[a] * t);
    const double Ns = 0.25 * xi_a[a] * (1 + eta_a[a] * t);
    const double Nt = 0.25 * eta_a[a] * (1 + xi_a[a] * s);
    for (int i = 0; i < 3; ++i) {
      m.x[i] += N * X[3 * a + i];
      m.xs[i] += Ns * X[3 * a + i];
      m.xe[i] += Nt * X[3 * a + i];
    }
  }
  return m;
}

Projection project_onto_quad(const double X[12], const double p[3], double tolerance) {
  Projection out;
  // x_{,xi eta} = (x1 - x2 + x3 - x4)/4 is constant on a bilinear face.
  double xst[3];
  for (int i = 0; i < 3; ++i) xst[i] = 0.25 * (X[i] - X[3 + i] + X[6 + i] - X[9 + i]);
  double s = 0.0, t = 0.0;
  bool converged = false;
  for (int it = 0; it < 20; ++it) {
    const FaceMap m = face_map(X, s, t);
    double r[3];
    for (int i = 0; i < 3; ++i) r[i] = m.x[i] - p[i];
    const double g1 = r[0] * m.xs[0] + r[1] * m.xs[1] + r[2] * m.xs[2];
    const double g2 = r[0] * m.xe[0] + r[1] * m.xe[1] + r[2] * m.xe[2];
    const double a11 = m.xs[0] * m.xs[0] + m.xs[1] * m.xs[1] + m.xs[2] * m.xs[2];
    const double a22 = m.xe[0] * m.xe[0] + m.xe[1] * m.xe[1] + m.xe[2] * m.xe[2];
    const double a12 = m.xs[0] * m.xe[0] + m.xs[1] * m.xe[1] + m.xs[2] * m.xe[2] +
                       r[0] * xst[0] + r[1] * xst[1] + r[2] * xst[2];
    const double det = a11 * a22 - a12 * a12;
    if (!(std::abs(det) > 0.0)) break;
    const double ds = (a22 * g1 - a12 * g2) / det, dt = (a11 * g2 - a12 * g1) / det;
    s -= ds;
    t -= dt;
    if (std::abs(s) > 10.0 || std::abs(t) > 10.0) break;  // far outside: the edge search decides
    if (std::abs(ds) < 1e-12 && std::abs(dt) < 1e-12) {
      converged = true;
      break;
    }
  }
  if (converged && std::abs(s) <= 1.0 + tolerance && std::abs(t) <= 1.0 + tolerance) {
    finish(X, p, std::clamp(s, -1.0, 1.0), std::clamp(t, -1.0, 1.0), out);
    // Keep the unclipped gap: the point is over the face within the tolerance band.
    out.interior = true;
    return out;
  }
  return project_onto_quad_boundary(X, p);
}

Projection project_onto_quad_boundary(const double X[12], const double p[3]) {
  Projection out;
  double best = INFINITY, bs = 0.0, bt = 0.0;
  for (int e = 0; e < 4; ++e) {
    double es, et, d2;
    closest_on_edge(X, p, e, (e + 1) % 4, es, et, d2);
    if (d2 < best) {
      best = d2;
      bs = es;
      bt = et;
    }
  }
  finish(X, p, bs, bt, out);
  out.interior = false;
  return out;
}

}  // namespace tribex::contact
