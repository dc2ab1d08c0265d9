// SPDX-License-Identifier: MIT
// Greenwood-Williamson contact models in nondimensional form (report Section 4.3-4.5).
//
// Heights z and separation t = d / sigma_s are in units of the summit-height standard deviation
// sigma_s; every asperity has radius R (the continuous and population models) and Hertz response
//   f = (4/3) E* sqrt(R) w^{3/2},  a = pi R w       (Eq. 4.4, w = z - d the interference).
// Scales: count by N (number of summits), area by pi R sigma_s N, load by (4/3) E* sqrt(R) sigma_s^{3/2} N.
// Then the continuous GW model is  n(t) = F_0(t), a(t) = F_1(t), p(t) = F_{3/2}(t)   (Eq. 4.1 with 4.9).
#pragma once

#include <cstdint>
#include <vector>

namespace tribex::gw {

struct GwPoint {
  double t = 0.0;      // separation d / sigma_s
  double count = 0.0;  // fraction of asperities in contact
  double area = 0.0;   // A / (pi R sigma_s N)
  double load = 0.0;   // P / ((4/3) E* sqrt(R) sigma_s^{3/2} N)
};

/// Continuous Gaussian GW at separation t.
GwPoint continuous_gw(double t);

/// Discrete GW (Eq. 4.2) over a finite population of summit heights z_i (units of sigma_s).
GwPoint discrete_gw(const std::vector<double>& heights, double t);

/// N heights drawn from the standard normal with a seeded Mersenne twister (Box-Muller).
std::vector<double> gaussian_population(std::size_t n, std::uint64_t seed);
/// N heights at the normal quantiles (i + 1/2)/N: a stratified population without sampling noise.
std::vector<double> stratified_gaussian_population(std::size_t n);

/// DMT-adhesive GW (Eqs. 4.10-4.12, docs/theory.md 10.4). beta = 2 pi W R / ((4/3) E* sqrt(R) sigma_s^{3/2})
/// = 3 pi W sqrt(R) / (2 E* sigma_s^{3/2}) is the adhesion force of one contacting asperity in load units.
/// Contacting asperities carry the Hertz force minus 2 pi W R; with z0 > 0 (units of sigma_s) the
/// asperities out of contact at gap s feel the Derjaguin 3-9 attraction
///   -2 pi W R [(4/3)(z0/(s+z0))^2 - (1/3)(z0/(s+z0))^8],
/// continuous with the contact value at s = 0; z0 = 0 keeps the report's contact-only form.
/// Returns the applied load (Hertz minus adhesion) in the load scale; area is the Hertz F_1(t).
GwPoint dmt_gw(double t, double beta, double z0 = 0.0);
GwPoint dmt_gw_discrete(const std::vector<double>& heights, double t, double beta, double z0 = 0.0);

/// The Tabor parameter of one asperity in these units (docs/theory.md 10.4): with W/E* = 2 beta
/// sigma_s^{3/2}/(3 pi sqrt(R)), mu_T = (R W^2/(E*^2 z0^3))^(1/3) = (2 beta/(3 pi))^(2/3)/z0 (z0 in sigma_s;
/// R cancels). The DMT per-asperity law assumes mu_T <= 0.3 (tools/common/tabor.hpp).
double asperity_tabor(double beta, double z0);

/// GW-like tangential model (report Fig. 4.11): each contacting asperity sticks with the Mindlin
/// stiffness k = 8 G* a (a = sqrt(R w)) until its shear capacity tau* pi R w, then slides.
/// In units of slip delta_ref = pi tau* sqrt(R sigma_s) / (8 G*) and force tau* pi R sigma_s N,
/// one asperity carries min(sqrt(w) * slip, w) and full sliding gives T = F_1(t) (= tau* A).
double tangential_gw(double t, double slip);
double tangential_gw_discrete(const std::vector<double>& heights, double t, double slip);

}  // namespace tribex::gw
