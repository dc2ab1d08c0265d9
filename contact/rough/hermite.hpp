// SPDX-License-Identifier: MIT
// Cubic Hermite interpolation on [0, 1] with end values f0, f1 and end slopes already multiplied by
// the spacing (m0, m1): the tabulated rough-surface laws (models/rough_surface.cpp,
// rough/noncontact_attraction.cpp) store each function with its exact derivative.
#pragma once

namespace tribex::contact {

inline double hermite(double s, double f0, double f1, double m0, double m1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * f1 + (s3 - s2) * m1;
}
/// d/ds of hermite(); divide by the spacing for the derivative in the table's variable.
inline double hermite_slope(double s, double f0, double f1, double m0, double m1) {
  const double s2 = s * s;
  return (6 * s2 - 6 * s) * f0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * f1 + (3 * s2 - 2 * s) * m1;
}

}  // namespace tribex::contact
