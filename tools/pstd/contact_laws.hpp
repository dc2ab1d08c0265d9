// SPDX-License-Identifier: MIT
// Elastic single-asperity laws of the PSTD model (seed report, Section 2.1.9).
//
// 2-D line contact (cylinder of radius R' on a half-plane, plane strain), per unit out-of-plane length,
// report eq. (2.5):
//   delta = (a^2 / (4R')) (2 ln(4R'/a) - 1),      P = pi a^2 E' / (4R')   [P in N/m]
// delta(a) rises from 0 to its maximum delta_max = 4R' e^-2 at a = 4R'/e and falls beyond, so the
// physical branch a in [0, 4R'/e] is inverted; interferences at or above delta_max are outside the
// law's range and are clamped to a = 4R'/e (the caller counts them).
//
// 3-D Hertz (sphere of radius R' on a half-space), report eq. (2.6):
//   a = sqrt(delta R'),   P = (4/3) E' sqrt(delta^3 R')   [P in N]
//
// E' is the effective (plane-strain) modulus 1/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2. Everything is SI.
#pragma once

namespace tribex::pstd {

enum class ContactLaw { line_2d, hertz_3d };

/// 1/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2, Pa.
double effective_modulus(double e1, double nu1, double e2, double nu2);

/// Largest interference the 2-D relation can carry: 4R' e^-2 (reached at a = 4R'/e).
double line_contact_max_interference(double radius);
/// delta(a) of eq. (2.5); a in [0, 4R'/e].
double line_contact_interference(double half_width, double radius);
/// a(delta), the inverse of eq. (2.5) on the branch a <= 4R'/e. Solved as g(t) = ln(2t-1) - 2t - ln(delta/4R') = 0
/// with t = ln(4R'/a) >= 1 by Newton safeguarded with bisection (g is concave and decreasing, so Newton
/// converges monotonically once past the root). Returns 0 for delta <= 0 and 4R'/e for delta >= delta_max;
/// *clamped (if given) says whether the latter happened.
double line_contact_half_width(double interference, double radius, bool* clamped = nullptr);
/// P = pi a^2 E'/(4R'), N/m.
double line_contact_load(double half_width, double radius, double modulus);
/// dP/d(delta) = pi E' / (2 (ln(4R'/a) - 1)), N/m^2; from dP/da = pi a E'/(2R') and
/// d(delta)/da = (a/R')(ln(4R'/a) - 1).
double line_contact_stiffness(double half_width, double radius, double modulus);

/// a = sqrt(delta R'), m.
double hertz_half_width(double interference, double radius);
/// P = (4/3) E' sqrt(delta^3 R'), N.
double hertz_load(double interference, double radius, double modulus);
/// dP/d(delta) = 2 E' sqrt(delta R') = 2 E' a, N/m.
double hertz_stiffness(double interference, double radius, double modulus);

}  // namespace tribex::pstd
