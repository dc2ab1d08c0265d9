// SPDX-License-Identifier: MIT
#include "solver/hex8/geometry.hpp"

#include <cmath>

#include "materials/small_matrix.hpp"
#include "solver/hex8/sum_factorized.hpp"

namespace tribex::solver::hex8 {
namespace {

// Reference coordinates of the 8 nodes (docs/theory.md 2.1 order).
constexpr double xi_n[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
constexpr double eta_n[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
constexpr double zeta_n[8] = {-1, -1, -1, -1, 1, 1, 1, 1};

// dN_I/d(xi,eta,zeta) at (x, y, z): out[3][8].
void reference_gradients(double x, double y, double z, double out[24]) {
  for (int I = 0; I < 8; ++I) {
    out[I] = 0.125 * xi_n[I] * (1 + eta_n[I] * y) * (1 + zeta_n[I] * z);
    out[8 + I] = 0.125 * eta_n[I] * (1 + xi_n[I] * x) * (1 + zeta_n[I] * z);
    out[16 + I] = 0.125 * zeta_n[I] * (1 + xi_n[I] * x) * (1 + eta_n[I] * y);
  }
}

// J_ij = dx_i/dxi_j and its adjugate; returns det J.
double jacobian(const double X[24], const double dN[24], double adj[9]) {
  double J[9] = {};
  for (int I = 0; I < 8; ++I)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J[3 * i + j] += X[3 * I + i] * dN[8 * j + I];
  // adj(J) = cof(J)^T
  double C[9];
  const double det = materials::cofactor3(J, C);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) adj[3 * i + j] = C[3 * j + i];
  return det;
}

constexpr double g = 0.57735026918962576451;  // 1/sqrt(3)

}  // namespace

double gradient_operator(const double X[24], double B[24]) {
  for (int k = 0; k < 24; ++k) B[k] = 0.0;
  double volume = 0.0;
  double dN[24], adj[9];
  for (int p = 0; p < 8; ++p) {
    reference_gradients(xi_n[p] * g, eta_n[p] * g, zeta_n[p] * g, dN);
    volume += jacobian(X, dN, adj);
    // det J dN/dx_i = sum_j adj(J)_{ji} dN/dxi_j  (J^{-1} = adj(J)/det J)
    for (int i = 0; i < 3; ++i)
      for (int I = 0; I < 8; ++I)
        B[8 * i + I] += adj[i] * dN[I] + adj[3 + i] * dN[8 + I] + adj[6 + i] * dN[16 + I];
  }
  return volume;
}

void hourglass_coefficients(const double X[24], double volume, double c[12]) {
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) {
      double xg = 0.0;  // x_iJ Gamma_aJ
      for (int J = 0; J < 8; ++J) xg += X[3 * J + i] * hourglass_base[a][J];
      c[3 * a + i] = xg / volume;
    }
}

void hourglass_vectors(const double X[24], const double B[24], double volume, double gamma[32]) {
  double c[12];
  hourglass_coefficients(X, volume, c);
  for (int a = 0; a < 4; ++a)
    for (int I = 0; I < 8; ++I)
      gamma[8 * a + I] = hourglass_base[a][I] - (B[I] * c[3 * a] + B[8 + I] * c[3 * a + 1] + B[16 + I] * c[3 * a + 2]);
}

double characteristic_length(const double B[24], double volume) {
  double bb = 0.0;
  for (int k = 0; k < 24; ++k) bb += B[k] * B[k];
  return volume / std::sqrt(2.0 * bb);
}

double gauss_point_inverse_jacobians(const double X[24], double Q[72], double wdetJ[8]) {
  // the kernel's own arithmetic (sum_factorized.hpp), so that these are its values bit for bit
  double Xe[24], Qp[9][8];
  for (int I = 0; I < 8; ++I)
    for (int i = 0; i < 3; ++i) Xe[8 * i + I] = X[3 * I + i];
  inverse_jacobians_at_points(Xe, Qp, wdetJ);
  double volume = 0.0;
  bool inverted = false;
  for (int p = 0; p < 8; ++p) {
    inverted = inverted || !(wdetJ[p] > 0.0);
    volume += wdetJ[p];
    for (int k = 0; k < 9; ++k) Q[8 * k + p] = Qp[k][p];
  }
  return inverted ? -std::abs(volume) : volume;
}

double min_corner_jacobian(const double X[24]) {
  double dN[24], adj[9];
  reference_gradients(0, 0, 0, dN);
  const double centre = jacobian(X, dN, adj);
  double worst = centre;
  for (int p = 0; p < 8; ++p) {
    reference_gradients(xi_n[p], eta_n[p], zeta_n[p], dN);
    const double d = jacobian(X, dN, adj);
    if (d < worst) worst = d;
  }
  return centre > 0.0 ? worst / centre : worst;
}

}  // namespace tribex::solver::hex8
