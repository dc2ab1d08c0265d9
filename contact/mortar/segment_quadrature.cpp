// SPDX-License-Identifier: MIT
#include "contact/mortar/segment_quadrature.hpp"

#include <algorithm>
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

BilinearMap2::BilinearMap2(const double x[4], const double y[4]) {
  // x(xi, eta) = sum_a N_a x_a = c0 + c1 xi + c2 eta + c3 xi eta (nodes (--), (+-), (++), (-+)).
  const double* v[2] = {x, y};
  for (int i = 0; i < 2; ++i) {
    c0[i] = 0.25 * (v[i][0] + v[i][1] + v[i][2] + v[i][3]);
    c1[i] = 0.25 * (-v[i][0] + v[i][1] + v[i][2] - v[i][3]);
    c2[i] = 0.25 * (-v[i][0] - v[i][1] + v[i][2] + v[i][3]);
    c3[i] = 0.25 * (v[i][0] - v[i][1] + v[i][2] - v[i][3]);
  }
  const double size = std::abs(c1[0]) + std::abs(c1[1]) + std::abs(c2[0]) + std::abs(c2[1]);
  affine = std::abs(c3[0]) + std::abs(c3[1]) <= 1e-14 * size;
}

void BilinearMap2::invert(double px, double py, double& xi, double& eta) const {
  // Newton from the centre; the first step is the exact inverse of the affine part, so a
  // parallelogram (c3 = 0) needs no more.
  xi = 0.0;
  eta = 0.0;
  for (int it = 0; it < 20; ++it) {
    const double rx = c0[0] + c1[0] * xi + c2[0] * eta + c3[0] * xi * eta - px;
    const double ry = c0[1] + c1[1] * xi + c2[1] * eta + c3[1] * xi * eta - py;
    const double j11 = c1[0] + c3[0] * eta, j12 = c2[0] + c3[0] * xi;
    const double j21 = c1[1] + c3[1] * eta, j22 = c2[1] + c3[1] * xi;
    const double det = j11 * j22 - j12 * j21;
    if (det == 0.0) return;
    const double dxi = (j22 * rx - j12 * ry) / det, deta = (j11 * ry - j21 * rx) / det;
    xi -= dxi;
    eta -= deta;
    if (affine || std::abs(dxi) + std::abs(deta) < 1e-14) return;
  }
}

void invert_bilinear(const double x[4], const double y[4], double px, double py, double& xi, double& eta) {
  BilinearMap2(x, y).invert(px, py, xi, eta);
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
  s.map = BilinearMap2(s.polygon.x, s.polygon.y);
  return s;
}

namespace {

// Quick reject: the master's projected corners and the slave polygon have disjoint bounding boxes
// in the plane (most candidates of a broad-phase list).
bool disjoint_in_plane(const double mx[4], const double my[4], const Polygon2& slave) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  double slo[2] = {INFINITY, INFINITY}, shi[2] = {-INFINITY, -INFINITY};
  for (int a = 0; a < 4; ++a) {
    lo[0] = std::min(lo[0], mx[a]);
    hi[0] = std::max(hi[0], mx[a]);
    lo[1] = std::min(lo[1], my[a]);
    hi[1] = std::max(hi[1], my[a]);
    slo[0] = std::min(slo[0], slave.x[a]);
    shi[0] = std::max(shi[0], slave.x[a]);
    slo[1] = std::min(slo[1], slave.y[a]);
    shi[1] = std::max(shi[1], slave.y[a]);
  }
  return lo[0] >= shi[0] || hi[0] <= slo[0] || lo[1] >= shi[1] || hi[1] <= slo[1];
}

// Facing faces only (the reversed master runs counter-clockwise in the plane); a master face seen
// edge-on (projected area below 1 % of its own, i.e. tilted more than 89.4 degrees from the slave
// plane) has an ill-conditioned projected map.
bool faces_the_slave(const Polygon2& master, const double Y[12]) {
  const double projected = signed_area(master);
  double diag1[3], diag2[3];
  for (int i = 0; i < 3; ++i) {
    diag1[i] = Y[6 + i] - Y[i];
    diag2[i] = Y[9 + i] - Y[3 + i];
  }
  const double c[3] = {diag1[1] * diag2[2] - diag1[2] * diag2[1], diag1[2] * diag2[0] - diag1[0] * diag2[2],
                       diag1[0] * diag2[1] - diag1[1] * diag2[0]};
  return !(projected <= 0.01 * 0.5 * std::sqrt(dot(c, c)));  // (NaN: not rejected here, as before)
}

// The master face's unit normal at its parametric point (xm, em): the cross product of the
// tangents dx/dxi, dx/deta of the bilinear face.
void master_unit_normal(const double Y[12], double xm, double em, double n[3]) {
  double t1[3] = {0, 0, 0}, t2[3] = {0, 0, 0};
  for (int a = 0; a < 4; ++a) {
    const double Ns = 0.25 * xi_a[a] * (1 + eta_a[a] * em), Nt = 0.25 * eta_a[a] * (1 + xi_a[a] * xm);
    for (int i = 0; i < 3; ++i) {
      t1[i] += Ns * Y[3 * a + i];
      t2[i] += Nt * Y[3 * a + i];
    }
  }
  n[0] = t1[1] * t2[2] - t1[2] * t2[1];
  n[1] = t1[2] * t2[0] - t1[0] * t2[2];
  n[2] = t1[0] * t2[1] - t1[1] * t2[0];
  const double len = std::sqrt(dot(n, n));
  for (int i = 0; i < 3; ++i) n[i] /= len;
}

}  // namespace

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
  if (disjoint_in_plane(mx, my, slave.polygon)) return false;
  Polygon2 master;
  master.count = 4;
  for (int a = 0; a < 4; ++a) {
    master.x[a] = mx[3 - a];
    master.y[a] = my[3 - a];
  }
  if (!faces_the_slave(master, Y)) return false;
  const Polygon2 overlap = clip_convex(master, slave.polygon);
  if (overlap.count < 3) return false;
  // The overlap of convex polygons is convex: a fan of count - 2 triangles from its first vertex
  // (exact for the degree-4 integrands of the penalty), or with `master_normals` (adhesion, a law
  // that varies sharply within a face) of count triangles from its vertex centroid: twice the
  // points (0.11 % instead of 0.48 % on the coarsest sphere of tests/contact/face_adhesion_test).
  double cx = overlap.x[0], cy = overlap.y[0];
  int first = 1, triangles = overlap.count - 2;
  if (master_normals) {
    cx = cy = 0.0;
    for (int i = 0; i < overlap.count; ++i) {
      cx += overlap.x[i];
      cy += overlap.y[i];
    }
    cx /= overlap.count;
    cy /= overlap.count;
    first = 0;
    triangles = overlap.count;
  }
  const BilinearMap2& slave_map = slave.map;
  const BilinearMap2 master_map(mx, my);
  // Heights above the plane along n_s. Projection onto the plane is linear, so the slave and
  // master points found by inverting the projected maps both sit over the integration point and
  // x_m - x_s = (h_m - h_s) n_s exactly: g = h_m - h_s.
  double hs[4], hm[4];
  for (int a = 0; a < 4; ++a) {
    hs[a] = hm[a] = 0.0;
    for (int i = 0; i < 3; ++i) {
      hs[a] += (slave.X[3 * a + i] - slave.centre[i]) * slave.normal[i];
      hm[a] += (Y[3 * a + i] - slave.centre[i]) * slave.normal[i];
    }
  }
  // h_m = d0 + d1 xi + d2 eta + d3 xi eta in the master's parametric coordinates.
  const double d1 = 0.25 * (-hm[0] + hm[1] + hm[2] - hm[3]), d2 = 0.25 * (-hm[0] - hm[1] + hm[2] + hm[3]);
  const double d3 = 0.25 * (hm[0] - hm[1] + hm[2] - hm[3]);
  for (int t = first; t < first + triangles; ++t) {
    const int u = (t + 1) % overlap.count;
    const double ax = overlap.x[t] - cx, ay = overlap.y[t] - cy, bx = overlap.x[u] - cx, by = overlap.y[u] - cy;
    const double area = 0.5 * (ax * by - ay * bx);
    if (!(area > 0.0)) continue;
    q.area += area;
    for (const TrianglePoint& tp : triangle_rule.p) {
      // Point = c + l1 (v_t - c) + l2 (v_u - c) (barycentric coordinates, l3 on the fan centre c).
      const double px = cx + tp.l1 * ax + tp.l2 * bx, py = cy + tp.l1 * ay + tp.l2 * by;
      double xi, eta, xm, em;
      slave_map.invert(px, py, xi, eta);
      master_map.invert(px, py, xm, em);
      const int k = q.count++;
      q.weight[k] = tp.w * area;
      double* N = q.slave_shape[k];
      double* Phi = q.master_shape[k];
      shape(xi, eta, N);
      shape(xm, em, Phi);
      q.gap[k] = (Phi[0] * hm[0] + Phi[1] * hm[1] + Phi[2] * hm[2] + Phi[3] * hm[3]) -
                 (N[0] * hs[0] + N[1] * hs[1] + N[2] * hs[2] + N[3] * hs[3]);
      // grad h_m = J^-T (dh/dxi, dh/deta), J the in-plane Jacobian of the projected master map.
      const double jx_xi = master_map.c1[0] + master_map.c3[0] * em, jx_eta = master_map.c2[0] + master_map.c3[0] * xm;
      const double jy_xi = master_map.c1[1] + master_map.c3[1] * em, jy_eta = master_map.c2[1] + master_map.c3[1] * xm;
      const double h_xi = d1 + d3 * em, h_eta = d2 + d3 * xm;
      const double det = jx_xi * jy_eta - jy_xi * jx_eta;
      q.master_slope[k][0] = (jy_eta * h_xi - jy_xi * h_eta) / det;
      q.master_slope[k][1] = (jx_xi * h_eta - jx_eta * h_xi) / det;
      if (master_normals) master_unit_normal(Y, xm, em, q.master_normal[k]);
    }
  }
  return q.count > 0;
}

}  // namespace tribex::contact
