// SPDX-License-Identifier: MIT
// Identities of the hex8 gradient operator and hourglass vectors (physics.md 2.1-2.2).
#include <gtest/gtest.h>

#include <cmath>

#include "solver/hex8/geometry.hpp"

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
  // B_iI B_iI = 3 h^4 / 2 for a cube, so L_e = h / sqrt(3) (physics.md 1.4)
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

TEST(Hex8Geometry, GaussGradientsSumToMeanOperator) {
  double X[24], B[24], dNdX[192], w[8];
  distorted(X);
  const double V = gradient_operator(X, B);
  const double V2 = gauss_point_gradients(X, dNdX, w);
  EXPECT_NEAR(V2, V, 1e-13 * V);
  for (int k = 0; k < 24; ++k) {
    double s = 0.0;
    for (int g = 0; g < 8; ++g) s += w[g] * dNdX[24 * g + k];
    EXPECT_NEAR(s, B[k], 1e-13 * std::pow(V, 2.0 / 3.0));
  }
}

TEST(Hex8Geometry, InvertedElementIsDetected) {
  double X[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  X[3 * 6 + 2] = -0.5;  // push node 7 (+++) below the bottom face
  EXPECT_LE(min_corner_jacobian(X), 0.0);
}
