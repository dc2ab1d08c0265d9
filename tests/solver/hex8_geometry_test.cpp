// SPDX-License-Identifier: MIT
// Identities of the hex8 gradient operator and hourglass vectors (docs/theory.md 2.1-2.2).
#include <gtest/gtest.h>

#include <cmath>

#include "solver/hex8/geometry.hpp"
#include "solver/hex8/sum_factorized.hpp"

using namespace tribex::solver::hex8;

namespace {
// A distorted, non-parallelepiped hex (all corners moved), still valid.
void distorted(double X[24]) {
  const double base[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  const double jitter[24] = {0.05, -0.02, 0.03, 0.1,  0.04, -0.05, -0.03, 0.12, 0.02, 0.02, -0.06, 0.07,
                             -0.04, 0.03, 0.1,  0.06, -0.1, 0.05,  0.15,  0.05, -0.02, 0.0, 0.08, 0.2};
  for (int k = 0; k < 24; ++k) X[k] = 2.0e-9 * (base[k] + jitter[k]);  // nanometre scale on purpose
}
}  // namespace

TEST(Hex8Geometry, GradientOperatorIdentities) {
  double X[24], B[24];
  distorted(X);
  const double V = gradient_operator(X, B);
  ASSERT_GT(V, 0.0);
  const double scale = std::cbrt(V);
  for (int i = 0; i < 3; ++i) {
    double sum = 0.0;
    for (int I = 0; I < 8; ++I) sum += B[8 * i + I];
    EXPECT_NEAR(sum, 0.0, 1e-14 * scale * scale) << "sum_I B_iI = 0, i = " << i;
    for (int j = 0; j < 3; ++j) {
      double bx = 0.0;
      for (int I = 0; I < 8; ++I) bx += B[8 * i + I] * X[3 * I + j];
      EXPECT_NEAR(bx, i == j ? V : 0.0, 1e-13 * V) << "sum_I B_iI x_jI = V delta_ij";
    }
  }
}

TEST(Hex8Geometry, CubeValues) {
  const double h = 0.5e-9;
  double X[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  for (double& x : X) x *= h;
  double B[24];
  const double V = gradient_operator(X, B);
  EXPECT_NEAR(V, h * h * h, 1e-12 * h * h * h);
  // B_iI B_iI = 3 h^4 / 2 for a cube, so L_e = h / sqrt(3) (docs/theory.md 1.4)
  EXPECT_NEAR(characteristic_length(B, V), h / std::sqrt(3.0), 1e-12 * h);
  EXPECT_NEAR(min_corner_jacobian(X), 1.0, 1e-12);
}

TEST(Hex8Geometry, HourglassVectorsOrthogonalToLinearFields) {
  double X[24], B[24], gamma[32];
  distorted(X);
  const double V = gradient_operator(X, B);
  hourglass_vectors(X, B, V, gamma);
  const double L = std::cbrt(V);
  for (int a = 0; a < 4; ++a) {
    double sum = 0.0;
    for (int I = 0; I < 8; ++I) sum += gamma[8 * a + I];
    EXPECT_NEAR(sum, 0.0, 1e-12);
    for (int j = 0; j < 3; ++j) {
      double gx = 0.0;
      for (int I = 0; I < 8; ++I) gx += gamma[8 * a + I] * X[3 * I + j];
      EXPECT_NEAR(gx / L, 0.0, 1e-12) << "gamma_a . x_j, a = " << a << ", j = " << j;
    }
  }
}

namespace {
// Direct route for comparison: dN_I/dX_k at Gauss point p from the shape functions and J^{-1}.
void direct_point_gradients(const double X[24], double dNdX[8][3][8]) {
  const double s[3][8] = {{-1, 1, 1, -1, -1, 1, 1, -1}, {-1, -1, 1, 1, -1, -1, 1, 1}, {-1, -1, -1, -1, 1, 1, 1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  for (int p = 0; p < 8; ++p) {
    double dN[3][8], J[3][3] = {};
    for (int I = 0; I < 8; ++I)
      for (int d = 0; d < 3; ++d) {
        dN[d][I] = 0.125 * s[d][I];
        for (int o = 0; o < 3; ++o)
          if (o != d) dN[d][I] *= 1.0 + s[o][I] * s[o][p] * g;
        for (int i = 0; i < 3; ++i) J[i][d] += X[3 * I + i] * dN[d][I];
      }
    const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                       J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                       J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    double Ji[3][3];  // inverse by cofactors
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        Ji[b][a] = (J[(a + 1) % 3][(b + 1) % 3] * J[(a + 2) % 3][(b + 2) % 3] -
                    J[(a + 1) % 3][(b + 2) % 3] * J[(a + 2) % 3][(b + 1) % 3]) / det;
    for (int k = 0; k < 3; ++k)
      for (int I = 0; I < 8; ++I) {
        dNdX[p][k][I] = 0.0;
        for (int d = 0; d < 3; ++d) dNdX[p][k][I] += dN[d][I] * Ji[d][k];
      }
  }
}
}  // namespace

TEST(Hex8Geometry, SumFactorisedGradientsAndForcesMatchTheShapeFunctions) {
  double X[24], Q[9][8], w[8], dNdX[8][3][8];
  distorted(X);
  gauss_point_inverse_jacobians(X, &Q[0][0], w);
  direct_point_gradients(X, dNdX);
  // a non-linear nodal field (nm-scale displacements on a 2 nm element)
  double ue[24];
  for (int k = 0; k < 24; ++k) ue[k] = 1e-10 * std::sin(1.7 * k + 0.3);
  double G[3][3][8], H[9][8];
  reference_gradients_at_points(ue, G);
  for (int p = 0; p < 8; ++p) {
    double Hp[9];
    point_gradient(G, Q, p, Hp);
    for (int k = 0; k < 9; ++k) H[k][p] = Hp[k];
  }
  for (int p = 0; p < 8; ++p)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        double h = 0.0;
        for (int I = 0; I < 8; ++I) h += ue[8 * i + I] * dNdX[p][k][I];
        EXPECT_NEAR(H[3 * i + k][p], h, 1e-14) << "point " << p << " H_" << i << k;
      }
  // forces from arbitrary weighted point stresses (Pa m^3 = N m)
  double Sw[9][8], fe[24] = {};
  for (int k = 0; k < 9; ++k)
    for (int p = 0; p < 8; ++p) Sw[k][p] = 1e-18 * std::cos(0.9 * k + 2.1 * p);
  add_point_forces(Sw, Q, fe);
  for (int i = 0; i < 3; ++i)
    for (int I = 0; I < 8; ++I) {
      double f = 0.0;
      for (int p = 0; p < 8; ++p)
        for (int k = 0; k < 3; ++k) f += Sw[3 * i + k][p] * dNdX[p][k][I];
      EXPECT_NEAR(fe[8 * i + I], f, 1e-14 * 1e-18 / 2e-9) << "f_" << i << " node " << I;
    }
}

TEST(Hex8Geometry, GaussPointOperatorsReproduceLinearFieldsAndTheMeanOperator) {
  double X[24], B[24], Q[9][8], w[8];
  distorted(X);
  const double V = gradient_operator(X, B);
  EXPECT_NEAR(gauss_point_inverse_jacobians(X, &Q[0][0], w), V, 1e-13 * V);
  // patch test: u = A X gives H = A at every point
  const double A[9] = {1e-3, -2e-3, 5e-4, 3e-3, 2e-3, -1e-3, -4e-4, 7e-4, 1.5e-3};
  double ue[24];
  for (int I = 0; I < 8; ++I)
    for (int i = 0; i < 3; ++i)
      ue[8 * i + I] = A[3 * i] * X[3 * I] + A[3 * i + 1] * X[3 * I + 1] + A[3 * i + 2] * X[3 * I + 2];
  double G[3][3][8];
  reference_gradients_at_points(ue, G);
  for (int p = 0; p < 8; ++p) {
    double H[9];
    point_gradient(G, Q, p, H);
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(H[k], A[k], 1e-15) << "point " << p << " component " << k;
  }
  // a unit stress S = I at every point gives f_iI = sum_p w_p dN_I/dX_i = B_iI
  double Sw[9][8] = {}, fe[24] = {};
  for (int p = 0; p < 8; ++p) Sw[0][p] = Sw[4][p] = Sw[8][p] = w[p];
  add_point_forces(Sw, Q, fe);
  for (int k = 0; k < 24; ++k) EXPECT_NEAR(fe[k], B[k], 1e-13 * std::pow(V, 2.0 / 3.0));
}

TEST(Hex8Geometry, InvertedElementIsDetected) {
  double X[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  X[3 * 6 + 2] = -0.5;  // push node 7 (+++) below the bottom face
  EXPECT_LE(min_corner_jacobian(X), 0.0);
}
