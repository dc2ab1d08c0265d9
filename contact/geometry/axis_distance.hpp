// SPDX-License-Identifier: MIT
// Distance of a point from the contact axis (a point on it and a unit direction), for the contact
// radii: r = x - p, r_perp = r - (r . d) d, distance^2 = |r_perp|^2.
#pragma once

#include <cmath>

namespace tribex::contact {

/// Squared distance of x [3] from the axis through `point` [3] along the unit vector `dir` [3], m^2.
inline double axis_distance_squared(const double* x, const double* point, const double* dir) {
  double r[3], along = 0.0;
  for (int i = 0; i < 3; ++i) {
    r[i] = x[i] - point[i];
    along += r[i] * dir[i];
  }
  double r2 = 0.0;
  for (int i = 0; i < 3; ++i) r2 += (r[i] - along * dir[i]) * (r[i] - along * dir[i]);
  return r2;
}

/// Distance of x [3] from the axis through `point` [3] along the unit vector `dir` [3], m.
inline double axis_distance(const double* x, const double* point, const double* dir) {
  return std::sqrt(axis_distance_squared(x, point, dir));
}

}  // namespace tribex::contact
