// SPDX-License-Identifier: MIT
#include "contact/mortar/segment_quadrature.hpp"

#include <cmath>

namespace tribex::contact {
namespace {

constexpr double xi_a[4] = {-1, 1, 1, -1};
constexpr double eta_a[4] = {-1, -1, 1, 1};

void shape(double xi, double eta, double N[4]) {
  for (int a = 0; a < 4; ++a) N[a] = 0.25 * (1 + xi_a[a] * xi) * (1 + eta_a[a] * eta);
}

// 7-point rule of degree 5 on a triangle (Radon 1948; Dunavant 1985, n = 5): barycentric
// coordinates (l1, l2; l3 = 1 - l1 - l2) and weights as fractions of the triangle's area.
struct TrianglePoint {
  double l1, l2, w;
};
struct Degree5Rule {
  TrianglePoint p[7];
  Degree5Rule() {
    const double s = std::sqrt(15.0);
    const double a1 = (6.0 - s) / 21.0, b1 = (9.0 + 2.0 * s) / 21.0, w1 = (155.0 - s) / 1200.0;
    const double a2 = (6.0 + s) / 21.0, b2 = (9.0 - 2.0 * s) / 21.0, w2 = (155.0 + s) / 1200.0;
    p[0] = {1.0 / 3.0, 1.0 / 3.0, 9.0 / 40.0};
    p[1] = {a1, a1, w1};
    p[2] = {a1, b1, w1};
    p[3] = {b1, a1, w1};
    p[4] = {a2, a2, w2};
    p[5] = {a2, b2, w2};
    p[6] = {b2, a2, w2};
  }
};
const Degree5Rule triangle_rule;

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

void invert_bilinear(const double x[4], const double y[4], double px, double py, double& xi, double& eta) {
  xi = 0.0;
  eta = 0.0;
  for (int it = 0; it < 20; ++it) {
    double N[4], rx = -px, ry = -py, j11 = 0, j12 = 0, j21 = 0, j22 = 0;
    shape(xi, eta, N);
    for (int a = 0; a < 4; ++a) {
      const double Ns = 0.25 * xi_a[a] * (1 + eta_a[a] * eta), Nt = 0.25 * eta_a[a] * (1 + xi_a[a] * xi);
      rx += N[a] * x[a];
      ry += N[a] * y[a];
      j11 += Ns * x[a];
      j12 += Nt * x[a];
      j21 += Ns * y[a];
      j22 += Nt * y[a];
    }
    const double det = j11 * j22 - j12 * j21;
    if (det == 0.0) return;
    const double dxi = (j22 * rx - j12 * ry) / det, deta = (j11 * ry - j21 * rx) / det;
    xi -= dxi;
    eta -= deta;
    if (std::abs(dxi) + std::abs(deta) < 1e-14) return;
  }
}

SlaveFacePlane slave_face_plane(const double X[12]) {
  SlaveFacePlane s;
  for (int k = 0; k < 12; ++k) s.X[k] = X[k];
  double d1[3], d2[3];
  for (int i = 0; i < 3; ++i) {
    s.centre[i] = 0.25 * (X[i] + X[3 + i] + X[6 + i] + X[9 + i]);
    d1[i] = X[6 + i] - X[i];      // diagonal 0 -> 2
    d2[i] = X[9 + i] - X[3 + i];  // diagonal 1 -> 3
  }
  // Normal of the bilinear face's mean plane: d1 x d2 (counter-clockwise nodes: outward).
  double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  const double len = std::sqrt(dot(n, n));
  for (int i = 0; i < 3; ++i) s.normal[i] = n[i] / len;
  // e1 along the first edge projected into the plane, e2 = n x e1.
  double e[3];
  for (int i = 0; i < 3; ++i) e[i] = X[3 + i] - X[i];
  const double en = dot(e, s.normal);
  for (int i = 0; i < 3; ++i) e[i] -= en * s.normal[i];
  const double el = std::sqrt(dot(e, e));
  for (int i = 0; i < 3; ++i) s.e1[i] = e[i] / el;
  s.e2[0] = s.normal[1] * s.e1[2] - s.normal[2] * s.e1[1];
  s.e2[1] = s.normal[2] * s.e1[0] - s.normal[0] * s.e1[2];
  s.e2[2] = s.normal[0] * s.e1[1] - s.normal[1] * s.e1[0];
  s.polygon.count = 4;
  for (int a = 0; a < 4; ++a) {
    double r[3];
    for (int i = 0; i < 3; ++i) r[i] = X[3 * a + i] - s.centre[i];
    s.polygon.x[a] = dot(r, s.e1);
    s.polygon.y[a] = dot(r, s.e2);
  }
  return s;
}

bool integrate_segment(const SlaveFacePlane& slave, const double Y[12], SegmentQuadrature& q, bool master_normals) {
  q.count = 0;
  q.area = 0.0;
  // Master corners in the slave plane. Seen from the slave's outward side a facing master face
  // runs clockwise (its own outward normal points back at the slave): reversed, it is
  // counter-clockwise; a master face that runs counter-clockwise faces away and is skipped.
  double mx[4], my[4];
  for (int a = 0; a < 4; ++a) {
    double r[3];
    for (int i = 0; i < 3; ++i) r[i] = Y[3 * a + i] - slave.centre[i];
    mx[a] = dot(r, slave.e1);
    my[a] = dot(r, slave.e2);
  }
  Polygon2 master;
  master.count = 4;
  for (int a = 0; a < 4; ++a) {
    master.x[a] = mx[3 - a];
    master.y[a] = my[3 - a];
  }
  if (signed_area(master) <= 0.0) return false;
  const Polygon2 overlap = clip_convex(master, slave.polygon);
  if (overlap.count < 3) return false;
  double cx = 0.0, cy = 0.0;
  for (int i = 0; i < overlap.count; ++i) {
    cx += overlap.x[i];
    cy += overlap.y[i];
  }
  cx /= overlap.count;
  cy /= overlap.count;
  const double* sx = slave.polygon.x;
  const double* sy = slave.polygon.y;
  for (int t = 0; t < overlap.count; ++t) {
    const int u = (t + 1) % overlap.count;
    const double ax = overlap.x[t] - cx, ay = overlap.y[t] - cy, bx = overlap.x[u] - cx, by = overlap.y[u] - cy;
    const double area = 0.5 * (ax * by - ay * bx);
    if (!(area > 0.0)) continue;
    q.area += area;
    for (const TrianglePoint& tp : triangle_rule.p) {
      // Point = centroid + l1 (v_t - c) + l2 (v_u - c) (barycentric with l3 on the centroid).
      const double px = cx + tp.l1 * ax + tp.l2 * bx, py = cy + tp.l1 * ay + tp.l2 * by;
      double xi, eta, xm, em;
      invert_bilinear(sx, sy, px, py, xi, eta);
      invert_bilinear(mx, my, px, py, xm, em);
      const int k = q.count++;
      q.weight[k] = tp.w * area;
      shape(xi, eta, q.slave_shape[k]);
      shape(xm, em, q.master_shape[k]);
      double g = 0.0;
      for (int i = 0; i < 3; ++i) {
        double xs = 0.0, xmaster = 0.0;
        for (int a = 0; a < 4; ++a) {
          xs += q.slave_shape[k][a] * slave.X[3 * a + i];
          xmaster += q.master_shape[k][a] * Y[3 * a + i];
        }
        g += (xmaster - xs) * slave.normal[i];
      }
      q.gap[k] = g;
      // grad h_m = J^-T (dh/dxi, dh/deta), J the in-plane Jacobian of the projected master map.
      double jx_xi = 0, jx_eta = 0, jy_xi = 0, jy_eta = 0, h_xi = 0, h_eta = 0;
      for (int a = 0; a < 4; ++a) {
        const double Ns = 0.25 * xi_a[a] * (1 + eta_a[a] * em), Nt = 0.25 * eta_a[a] * (1 + xi_a[a] * xm);
        double h = 0.0;
        for (int i = 0; i < 3; ++i) h += Y[3 * a + i] * slave.normal[i];
        jx_xi += Ns * mx[a];
        jx_eta += Nt * mx[a];
        jy_xi += Ns * my[a];
        jy_eta += Nt * my[a];
        h_xi += Ns * h;
        h_eta += Nt * h;
      }
      if (master_normals) {
        double t1[3] = {0, 0, 0}, t2[3] = {0, 0, 0};
        for (int a = 0; a < 4; ++a) {
          const double Ns = 0.25 * xi_a[a] * (1 + eta_a[a] * em), Nt = 0.25 * eta_a[a] * (1 + xi_a[a] * xm);
          for (int i = 0; i < 3; ++i) {
            t1[i] += Ns * Y[3 * a + i];
            t2[i] += Nt * Y[3 * a + i];
          }
        }
        double* n = q.master_normal[k];
        n[0] = t1[1] * t2[2] - t1[2] * t2[1];
        n[1] = t1[2] * t2[0] - t1[0] * t2[2];
        n[2] = t1[0] * t2[1] - t1[1] * t2[0];
        const double len = std::sqrt(dot(n, n));
        for (int i = 0; i < 3; ++i) n[i] /= len;
      }
      // Solve [[jx_xi, jy_xi], [jx_eta, jy_eta]] s = (h_xi, h_eta).
      const double det = jx_xi * jy_eta - jy_xi * jx_eta;
      q.master_slope[k][0] = (jy_eta * h_xi - jy_xi * h_eta) / det;
      q.master_slope[k][1] = (jx_xi * h_eta - jx_eta * h_xi) / det;
    }
  }
  return q.count > 0;
}

}  // namespace tribex::contact
