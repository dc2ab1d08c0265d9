// SPDX-License-Identifier: MIT
// 3x3 helpers shared by the material models and the element kernels (row-major double[9]).
#pragma once

namespace tribex::materials {

/// Cofactor matrix C of A (C_ij = (-1)^(i+j) minor_ij, so C = det(A) A^{-T}); returns det(A).
template <class T>
inline T cofactor3(const T A[9], T C[9]) {
  C[0] = A[4] * A[8] - A[5] * A[7];
  C[1] = A[5] * A[6] - A[3] * A[8];
  C[2] = A[3] * A[7] - A[4] * A[6];
  C[3] = A[2] * A[7] - A[1] * A[8];
  C[4] = A[0] * A[8] - A[2] * A[6];
  C[5] = A[1] * A[6] - A[0] * A[7];
  C[6] = A[1] * A[5] - A[2] * A[4];
  C[7] = A[2] * A[3] - A[0] * A[5];
  C[8] = A[0] * A[4] - A[1] * A[3];
  return A[0] * C[0] + A[1] * C[1] + A[2] * C[2];
}

}  // namespace tribex::materials
