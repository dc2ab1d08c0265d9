// SPDX-License-Identifier: MIT
// Hex8 geometry: shape-function gradients, the volume-integrated gradient operator of the
// uniform-strain (mean-quadrature) element, hourglass shape vectors and the characteristic length.
//
// Array layouts (all row-major, double):
//   X      [8][3]  nodal coordinates, node I at 3I..3I+2, node order of docs/theory.md 2.1 / mesh.hpp
//   B      [3][8]  B_iI = int_V dN_I/dx_i dV (m^2); component i at 8i..8i+7
//   gamma  [4][8]  Flanagan-Belytschko orthogonal hourglass vectors gamma_aI (dimensionless)
//   Q      [3][3][8] at the 8 Gauss points (point p at +/-1/sqrt(3) with node p's signs):
//                  Q[3j+k][p] = (dxi_j/dX_k)/8 = J^{-1}_jk / 8 (1/m); the 1/8 is the factor of the
//                  trilinear shape-function derivatives, folded in (sum_factorized.hpp)
//   wdetJ  [8]     Gauss weight times det J at each point (m^3)
#pragma once

namespace tribex::solver::hex8 {

/// B_iI = int_V dN_I/dx_i dV, evaluated exactly by 2x2x2 Gauss quadrature (the integrand,
/// adj(J) dN/dxi, is at most quadratic in each reference coordinate). Returns the volume V.
/// Properties: sum_I B_iI = 0 and sum_I B_iI x_jI = V delta_ij (tested).
double gradient_operator(const double X[24], double B[24]);

/// Flanagan-Belytschko hourglass vectors gamma_aI = Gamma_aI - (1/V) B_iI x_iJ Gamma_aJ, which
/// are orthogonal to every linear field (gamma_aI x_jI = 0), so linear motion creates no hourglass
/// force (docs/theory.md 2.2).
void hourglass_vectors(const double X[24], const double B[24], double volume, double gamma[32]);

/// Hourglass base vectors Gamma_aI (docs/theory.md 2.2): ~ eta*zeta, zeta*xi, xi*eta, xi*eta*zeta.
inline constexpr double hourglass_base[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                                {1, -1, -1, 1, -1, 1, 1, -1},
                                                {1, -1, 1, -1, 1, -1, 1, -1},
                                                {-1, 1, -1, 1, 1, -1, 1, -1}};

/// The hourglass vectors in factored form, gamma_aI = Gamma_aI - c_aj B_jI with
/// c_aj = (1/V) x_jJ Gamma_aJ (m^-2), c [4][3]: 12 numbers per element instead of 32, and the
/// products with u and f reuse the element's B0 sums (mean_quadrature.hpp).
void hourglass_coefficients(const double X[24], double volume, double c[12]);

/// Characteristic length of Flanagan & Belytschko, L_e = V / sqrt(2 B_iI B_iI) (= h/sqrt(3) for
/// a cube of side h); the element's stable step is L_e / c_d (docs/theory.md 1.4).
double characteristic_length(const double B[24], double volume);

/// Inverse Jacobians (over 8) and weights at the 2x2x2 Gauss points (fully integrated element), as
/// the kernel forms them each step (sum_factorized.hpp inverse_jacobians_at_points): the same bits.
/// Returns the volume; a non-positive det J at any point returns it as a negative value.
double gauss_point_inverse_jacobians(const double X[24], double Q[72], double wdetJ[8]);

/// Minimum of det J over the 8 corners divided by det J at the centre (1 for any parallelepiped);
/// <= 0 means an inverted corner.
double min_corner_jacobian(const double X[24]);

}  // namespace tribex::solver::hex8
