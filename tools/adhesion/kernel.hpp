// SPDX-License-Identifier: MIT
// The axisymmetric Boussinesq kernel integrated exactly over ring elements (docs/theory.md 6.7.2,
// Eq. 6.7.3): the normal surface displacement (both bodies, composite modulus E*) at radius r due to
// a unit uniform pressure on the annulus b1 < s < b2, from Johnson's disk solution
//   u(r; b) = (4/(pi E*)) b E(r/b)                          r <= b
//   u(r; b) = (4/(pi E*)) r [E(b/r) - (1 - b^2/r^2) K(b/r)]   r >  b
// (K, E complete elliptic integrals of modulus k), u_ring = u(r; b2) - u(r; b1).
#pragma once

#include <vector>

namespace tribex::adhesion {

/// (pi E*/4) u(r; b) for a unit pressure on the disk of radius b (m); u(r; 0) = 0.
double disk_displacement_scaled(double r, double b);

/// The influence matrix C (rows = `points`, columns = rings between consecutive `edges`), m/Pa:
/// gap change at points[i] per unit compressive pressure on ring j. Row-major, points.size() x (edges.size()-1).
std::vector<double> ring_influence(const std::vector<double>& points, const std::vector<double>& edges, double e_star);

}  // namespace tribex::adhesion
