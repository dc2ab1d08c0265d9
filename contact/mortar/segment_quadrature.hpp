// SPDX-License-Identifier: MIT
// Segment-to-segment (mortar) integration of one slave face against one master face (Puso and
// Laursen 2004, CMAME 193: 601-629, the "segment" approach): both faces are projected along the
// slave face normal onto the slave face's plane, the master polygon is clipped against the slave
// polygon (geometry/polygon_clip), the (convex) overlap polygon is cut into a fan of triangles
// (from its first vertex; for adhesion from its centroid, twice the points) and each triangle integrated with the 7-point degree-5 rule (Radon; Dunavant 1985,
// IJNME 21: 1129). At each point the slave and master parametric coordinates follow from
// inverting the projected bilinear maps, which gives the shape functions N_a (slave), Phi_k
// (master) and the gap g = (x_m - x_s) . n_s (> 0 apart, < 0 penetrated; n_s the slave face's
// outward unit normal, pointing toward the master). The master's slope grad h_m at the point gives
// the tangential part of the gap's gradient (dg/dx_slave,t = N_a grad h_m, dg/dx_master,t =
// -Phi_k grad h_m), so that the mortar forces are the gradient of their potential (energy-consistent
// on curved or tilted masters; zero on a flat master).
//
// Exactness: for flat parallelogram faces the parametric coordinates are affine in the plane, so
// N_a N_b, Phi_k N_b (degree 4) and the area are integrated exactly; for warped faces the plane
// projection is the usual mortar approximation.
#pragma once

#include "contact/geometry/polygon_clip.hpp"

namespace tribex::contact {

/// The bilinear map of a quad in a plane, x = c0 + c1 xi + c2 eta + c3 xi eta, corners (--), (+-),
/// (++), (-+); inverted by Newton from the centre (one step when it is a parallelogram, c3 = 0).
struct BilinearMap2 {
  double c0[2] = {0, 0}, c1[2] = {0, 0}, c2[2] = {0, 0}, c3[2] = {0, 0};
  bool affine = true;
  BilinearMap2() = default;
  BilinearMap2(const double x[4], const double y[4]);
  /// Parametric coordinates of (px, py); outside [-1, 1] for points outside the quad.
  void invert(double px, double py, double& xi, double& eta) const;
};

/// A slave face's projection plane: centre, unit normal (from the diagonals, outward of the slave
/// body), in-plane basis e1 x e2 = n, and the face as a counter-clockwise polygon in (e1, e2).
struct SlaveFacePlane {
  double X[12];  // face nodes [4][3]
  double centre[3], normal[3], e1[3], e2[3];
  Polygon2 polygon;
  BilinearMap2 map;  // of the polygon's corners
};

/// Integration points of one slave/master face pair (fixed capacity: a polygon of up to
/// Polygon2::capacity vertices gives as many triangles, 7 points each).
struct SegmentQuadrature {
  static constexpr int points_per_triangle = 7;
  static constexpr int capacity = Polygon2::capacity * points_per_triangle;
  int count = 0;
  double area = 0.0;                // overlap area (sum of the weights), m^2
  double weight[capacity];          // m^2
  double slave_shape[capacity][4];  // N_a at the point
  double master_shape[capacity][4]; // Phi_k at the point
  double gap[capacity];             // m
  double master_slope[capacity][2]; // grad h_m in (e1, e2): slope of the master's height h_m = x_m . n_s over the plane
  double master_normal[capacity][3];  // unit outward normal of the master face at the point (only if asked for)
};

/// `X` the slave face nodes [4][3] in the surface's counter-clockwise (outward) order.
SlaveFacePlane slave_face_plane(const double X[12]);

/// Integrates the overlap of master face `Y` [4][3] with the slave face. Returns false (count 0)
/// when the faces do not overlap in the plane or the master face does not face the slave (its
/// outward normal not opposed to n_s).
/// `master_normals` (adhesion): also fill master_normal (the traction acts along it), and use the
/// finer centroid fan.
bool integrate_segment(const SlaveFacePlane& slave, const double Y[12], SegmentQuadrature& q,
                       bool master_normals = false);

/// Parametric coordinates (xi, eta) of point (px, py) in the bilinear quad with corners
/// (x[a], y[a]), a = (--), (+-), (++), (-+): Newton from the centre (exact in one step for a
/// parallelogram). Points outside the quad give coordinates outside [-1, 1].
void invert_bilinear(const double x[4], const double y[4], double px, double py, double& xi, double& eta);

}  // namespace tribex::contact
