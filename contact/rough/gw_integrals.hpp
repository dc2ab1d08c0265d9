// SPDX-License-Identifier: MIT
// The Greenwood-Williamson integrals and the numerics they need.
//
//   F_n(t) = (1/sqrt(2 pi)) * int_t^inf (s - t)^n exp(-s^2/2) ds      (report Eq. 4.9)
//
// Closed forms: F_0(t) = erfc(t/sqrt2)/2, F_1(t) = phi(t) - t F_0(t). Other n >= 0 by quadrature of
// F_n(t) = phi(t) * int_0^inf u^n exp(-t u - u^2/2) du with u = s^2 (smooth integrand for
// half-integer n) on composite 20-point Gauss-Legendre panels: about 1e-14 relative for t in [-3, 8].
#pragma once

#include <functional>

namespace tribex::gw {

/// Standard normal density phi(t).
double normal_pdf(double t);
/// Upper tail Q(t) = P(Z > t) = F_0(t).
double normal_upper_tail(double t);
/// Inverse of the standard normal CDF, p in (0, 1) (bisection on erfc: exact to ~1e-15 in x).
double normal_quantile(double p);

/// F_n(t) for n >= 0 (exact closed forms for n = 0 and 1).
double gw_integral(double n, double t);
/// F_n(t) by quadrature for every n (used to check the closed forms).
double gw_integral_quadrature(double n, double t);

/// int_a^b f(x) dx with `panels` panels of 20-point Gauss-Legendre.
double gauss_legendre(const std::function<double(double)>& f, double a, double b, int panels);

}  // namespace tribex::gw
