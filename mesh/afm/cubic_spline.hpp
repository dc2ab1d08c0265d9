// SPDX-License-Identifier: MIT
// Interpolating cubic splines on uniformly spaced knots, and the interpolated surface of a height map
// built the report's way (Section 3.4): a spline through each row of pixels, then one through each column.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/afm/height_map.hpp"

namespace tribex::mesh::afm {

/// End conditions. natural: zero second derivative at both ends (error O(h^2) near the ends where
/// f'' != 0); not_a_knot: continuous third derivative at the second and last-but-one knots (O(h^4)
/// up to the ends, exact for cubics). The surface uses not_a_knot: a map edge is no inflection line.
enum class SplineEnds { natural, not_a_knot };

/// Interpolating cubic spline through (x0 + i h, y_i), i = 0..n-1. n = 2 gives the straight line,
/// n = 3 with not_a_knot the parabola. Outside [x0, x0 + (n-1) h] the end cubic pieces are continued
/// (used only for the half pixel between the outermost pixel centres and the map edge).
class CubicSpline {
 public:
  CubicSpline(double x0, double h, std::vector<double> values, SplineEnds ends = SplineEnds::not_a_knot);
  double operator()(double x) const;

 private:
  double x0_, h_;
  std::vector<double> y_, m_;  // values and second derivatives at the knots
};

/// Second derivatives M_i of the spline through equally spaced values: Thomas algorithm on
/// M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i+1} - 2 y_i + y_{i-1}) / h^2 for the interior knots, with
/// M_0 = M_{n-1} = 0 (natural) or M_0 = 2 M_1 - M_2, M_{n-1} = 2 M_{n-2} - M_{n-3} (not-a-knot).
std::vector<double> spline_moments(const double* y, std::size_t n, double h, SplineEnds ends);

/// The bicubic-spline surface (not-a-knot ends) through every pixel of a map. Pixel (ix, iy) sits at
/// its centre ((ix + 1/2) dx, (iy + 1/2) dy); the surface is defined on the whole map [0, nx dx] x [0, ny dy].
class SplineSurface {
 public:
  explicit SplineSurface(const HeightMap& map);
  /// Heights at the grid xs x ys, row-major [j * xs.size() + i] (m): splines along each pixel row
  /// evaluated at xs, then a spline along y through each of those columns evaluated at ys.
  std::vector<double> evaluate_grid(const std::vector<double>& xs, const std::vector<double>& ys) const;
  double operator()(double x, double y) const;

 private:
  const HeightMap& map_;
  std::vector<double> row_moments_;  // [iy][ix] second derivatives of each row's spline along x
};

}  // namespace tribex::mesh::afm
