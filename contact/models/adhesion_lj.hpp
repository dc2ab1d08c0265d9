// SPDX-License-Identifier: MIT
// The Lennard-Jones 3-9 half-space traction law of the Adhesion Model (docs/theory.md 6; report 3.2).
//
// Two half-spaces interacting by a 6-12 pair potential give, per unit area at separation h,
//   sigma_a(h) = (8W/(3 z0)) [ (z0/h)^3 - (z0/h)^9 ]        (Pa, positive = attractive)
//   Phi(h)     = -(4W/3) (z0/h)^2 + (W/3) (z0/h)^8           (J/m^2, dPhi/dh = sigma_a, Phi(z0) = -W)
// zero at h = z0, peak 16W/(9 sqrt(3) z0) = 1.0264 W/z0 at h = 3^(1/6) z0 = 1.2009 z0.
//
// Applied with hard (penalty) frictionless contact, the law is offset so that touching surfaces sit
// at its equilibrium: h = g + z0 for a gap g >= 0 (docs/theory.md 6.2). It is cut off at the separation
// h_c (measured like h, so h_c > z0; the capture gap is g_c = h_c - z0) and made continuous there by
// subtracting sigma_a(h_c) (docs/theory.md 6.3):
//   sigma_s(h) = sigma_a(h) - sigma_a(h_c)   for z0 <= h <= h_c, 0 beyond,
//   U(h)       = Phi(h) - Phi(h_c) - sigma_a(h_c) (h - h_c)   (dU/dh = sigma_s, U(h_c) = 0).
// The shift leaves a small repulsion sigma_a(h_c) at touching (0.26 % of the peak for h_c = 10 z0,
// 2.1 % for 5 z0), which the penalty contact carries; the work captured is -U(z0) (see captured_work).
#pragma once

#include <algorithm>
#include <cmath>

namespace tribex::contact {

struct AdhesionLaw {
  double work = 0.0;        // W, work of adhesion, J/m^2
  double z0 = 0.0;          // equilibrium separation, m
  double cutoff = 0.0;      // h_c, cut-off separation (measured like h), m; > z0
  double capture_gap() const { return cutoff - z0; }  // g_c = h_c - z0, m
};

/// sigma_a(h) = (8W/(3 z0)) [ (z0/h)^3 - (z0/h)^9 ], Pa, positive = attractive.
inline double lj_traction(double h, double work, double z0) {
  const double r3 = std::pow(z0 / h, 3);
  return 8.0 * work / (3.0 * z0) * (r3 - r3 * r3 * r3);
}

/// Phi(h) = -(4W/3)(z0/h)^2 + (W/3)(z0/h)^8, J/m^2 (energy per area of two half-spaces).
inline double lj_energy(double h, double work, double z0) {
  const double r2 = (z0 / h) * (z0 / h);
  return -4.0 * work / 3.0 * r2 + work / 3.0 * r2 * r2 * r2 * r2;
}

/// The applied (offset, cut-off, continuous) traction at gap g: sigma_s(g + z0), Pa; zero for
/// g < 0 (penalty contact) and for g > g_c.
inline double adhesive_traction(double gap, const AdhesionLaw& law) {
  const double h = gap + law.z0;
  if (gap < 0.0 || h > law.cutoff) return 0.0;
  return lj_traction(h, law.work, law.z0) - lj_traction(law.cutoff, law.work, law.z0);
}

/// The potential per area at gap g, U(g + z0) (J/m^2, <= 0 in the attractive range): the energy
/// that would be released by closing the gap from the cut-off; U(z0) for g < 0, 0 beyond g_c.
inline double adhesive_energy(double gap, const AdhesionLaw& law) {
  const double h = std::max(gap, 0.0) + law.z0;
  if (h > law.cutoff) return 0.0;
  const double hc = law.cutoff;
  return lj_energy(h, law.work, law.z0) - lj_energy(hc, law.work, law.z0) -
         lj_traction(hc, law.work, law.z0) * (h - hc);
}

/// Work to separate touching surfaces to beyond the cut-off with the applied law, -U(z0), J/m^2;
/// W (1 - (4/3)(z0/h_c)^2 + (1/3)(z0/h_c)^8) minus the shift's share (docs/theory.md 6.3).
inline double captured_work(const AdhesionLaw& law) { return -adhesive_energy(0.0, law); }

}  // namespace tribex::contact
