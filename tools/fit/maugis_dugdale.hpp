// SPDX-License-Identifier: MIT
// Maugis-Dugdale (MD) sphere-on-flat adhesive contact, solved exactly in Maugis' non-dimensional
// variables (docs/theory.md 8.4):
//   a_bar = a (K/(pi W R^2))^(1/3),  P_bar = P/(pi W R),  lambda = 2 sigma0 (R/(pi W K^2))^(1/3),
//   m = c/a (outer radius of the Dugdale zone over the contact radius), K = 4E*/3.
//   (1) (lambda a^2/2)[s + (m^2-2) atan s] + (4 lambda^2 a/3)[s atan s - m + 1] = 1,  s = sqrt(m^2-1)
//   (2) P_bar = a^3 - lambda a^2 [s + m^2 atan s]
// For a given a_bar, (1) is strictly increasing in m (dF/dm = lambda a^2 (s/m + m atan s) +
// (4 lambda^2 a/3)(m atan(s)/s + 1/m - 1) > 0), so m is found by bracketing and the Illinois method.
// Under load control the stable branch is a_bar >= a_bar at min P_bar (the pull-off).
#pragma once

namespace tribex::fit {

struct MaugisPoint {
  double a_bar = 0;  // contact radius
  double m = 1;      // c/a
  double p_bar = 0;  // applied load
  /// Load carried inside the contact, int_{r<a} p dA / (pi W R) = P_bar + (pi/2) lambda a^2 (m^2-1):
  /// the Dugdale stress sigma0 pulls on the annulus a < r < c.
  double carried_bar(double lambda) const;
};

class MaugisDugdale {
 public:
  /// lambda > 0 (throws std::invalid_argument otherwise).
  explicit MaugisDugdale(double lambda);
  double lambda() const { return lambda_; }
  /// Solves (1) for m, then (2).
  MaugisPoint at_radius(double a_bar) const;
  /// The load-controlled pull-off (minimum of P_bar over a_bar).
  const MaugisPoint& pull_off() const { return pull_off_; }
  /// The stable-branch solution at load p_bar >= pull_off().p_bar (Illinois root-finding in a_bar).
  MaugisPoint at_load(double p_bar) const;

 private:
  double lambda_;
  MaugisPoint pull_off_;
};

}  // namespace tribex::fit
