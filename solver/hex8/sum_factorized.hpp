// SPDX-License-Identifier: MIT
// The trilinear hex8's gradient at its 2x2x2 Gauss points, and the transposed operation (nodal
// forces from point stresses), by sum factorisation over the element's 12 edges.
//
// Why: dN_I/dxi = xi_I (1 + eta_I eta)(1 + zeta_I zeta)/8 does not depend on xi, so
//   du/dxi (eta, zeta) = (1/8) sum over the 4 xi-edges e of (u_e+ - u_e-)(1 + eta_e eta)(1 + zeta_e zeta),
// the same at the two points of each xi-line; likewise for eta and zeta. With the 1/8 folded into
// Q = J^{-1}/8 (geometry.hpp) the displacement gradient at point p is H_p = G_p Q_p, G_p[i][d] the
// edge interpolation above: about 600 flops per element against 1,150 for u_iI dN_I/dX_j at each
// point. Q and wdetJ themselves come from the reference coordinates by the same edge interpolation
// (inverse_jacobians_at_points), each step, instead of 80 stored numbers per element.
//
// T = double (one element) or double2, double4, double8 (elements one per lane; materials/lanes.hpp).
// Layouts: ue/fe [3][8] (component i of node I at 8i + I); Q [9][8] (Q_dk of point p at
// [3d + k][p]); the Gauss points are numbered as the nodes (point p at +-1/sqrt(3) with node p's
// signs), so the points on an edge's line carry the edge's node numbers.
#pragma once

#include "materials/small_matrix.hpp"

namespace tribex::solver::hex8 {

namespace edges {
// Edges along xi, eta, zeta, each listed by its two transverse coordinates (a, b) in the order
// (-,-), (+,-), (-,+), (+,+): (eta, zeta) for xi, (xi, zeta) for eta, (xi, eta) for zeta.
constexpr int minus_node[3][4] = {{0, 3, 4, 7}, {0, 1, 4, 5}, {0, 1, 3, 2}};
constexpr int plus_node[3][4] = {{1, 2, 5, 6}, {3, 2, 7, 6}, {4, 5, 7, 6}};
// The same edges seen from the nodes: node I is on edge edge_of[d][I] along d, at its
// sign_of[d][I] end (the node's own reference coordinate in d).
constexpr int edge_of[3][8] = {{0, 0, 1, 1, 2, 2, 3, 3}, {0, 1, 1, 0, 2, 3, 3, 2}, {0, 1, 3, 2, 0, 1, 3, 2}};
constexpr double sign_of[3][8] = {{-1, 1, 1, -1, -1, 1, 1, -1}, {-1, -1, 1, 1, -1, -1, 1, 1}, {-1, -1, -1, -1, 1, 1, 1, 1}};
constexpr double g = 0.57735026918962576451;  // 1/sqrt(3)

/// r(a, b) = sum_e d_e (1 + a_e a g)(1 + b_e b g) at the 4 (a, b) = (+-1, +-1), both in the order
/// above. The map is symmetric, so it also takes point values back to the edges (the transpose).
template <class T>
inline void bilinear_at_points(const T d[4], T r[4]) {
  // modal form: r = c0 + g a c_a + g b c_b + g^2 a b c_ab
  const T s01 = d[0] + d[1], d01 = d[1] - d[0], s23 = d[2] + d[3], d23 = d[3] - d[2];
  const T c0 = s01 + s23, cb = g * (s23 - s01), ca = g * (d01 + d23), cab = (g * g) * (d23 - d01);
  const T p_minus = c0 - ca, p_plus = c0 + ca, q_minus = cb - cab, q_plus = cb + cab;
  r[0] = p_minus - q_minus;
  r[1] = p_plus - q_plus;
  r[2] = p_minus + q_minus;
  r[3] = p_plus + q_plus;
}
}  // namespace edges

/// G[i][d][p] = 8 du_i/dxi_d at the 8 points (the 1/8 is in Q).
template <class T>
inline void reference_gradients_at_points(const T ue[24], T G[3][3][8]) {
  for (int i = 0; i < 3; ++i)
    for (int d = 0; d < 3; ++d) {
      T diff[4], r[4];
      for (int e = 0; e < 4; ++e) diff[e] = ue[8 * i + edges::plus_node[d][e]] - ue[8 * i + edges::minus_node[d][e]];
      edges::bilinear_at_points(diff, r);
      for (int e = 0; e < 4; ++e) {
        G[i][d][edges::minus_node[d][e]] = r[e];
        G[i][d][edges::plus_node[d][e]] = r[e];
      }
    }
}

/// The reference geometry at the 8 points from the element's reference coordinates Xe [3][8] (the
/// layout of ue): with G_p = 8 dX/dxi at point p (reference_gradients_at_points), J_p = G_p / 8, so
/// Q_p = J_p^{-1} / 8 = G_p^{-1} = adj(G_p) / det G_p and wdetJ_p = det J_p = det G_p / 512 (Gauss
/// weights 1). The fully integrated kernel forms these each step instead of reading 640 B of stored
/// operators per element (docs/measurements/2026-11-27-bench-element-kernels.md, "Reference geometry
/// rebuilt"): about 550 flops (200 for G, 43 per point) and one division per point, the same IEEE
/// sequence in every lane.
template <class T>
inline void inverse_jacobians_at_points(const T Xe[24], T Q[9][8], T wdetJ[8]) {
  T G[3][3][8];
  reference_gradients_at_points(Xe, G);
  for (int p = 0; p < 8; ++p) {
    T Gp[9], C[9];  // Gp[3i + d] = 8 dX_i/dxi_d; C its cofactors
    for (int i = 0; i < 3; ++i)
      for (int d = 0; d < 3; ++d) Gp[3 * i + d] = G[i][d][p];
    const T det = materials::cofactor3(Gp, C);
    const T inv_det = 1.0 / det;
    // (G^{-1})_dk = adj(G)_dk / det = C_kd / det
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 3; ++k) Q[3 * d + k][p] = C[3 * k + d] * inv_det;
    wdetJ[p] = det * (1.0 / 512.0);
  }
}

/// Displacement gradient at point p: H[3i + k] = du_i/dX_k = sum_d G[i][d][p] Q[3d + k][p].
template <class T>
inline void point_gradient(const T G[3][3][8], const T Q[9][8], int p, T H[9]) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) H[3 * i + k] = G[i][0][p] * Q[k][p] + G[i][1][p] * Q[3 + k][p] + G[i][2][p] * Q[6 + k][p];
}

/// Adds f_iI = sum_p w_p S_ik(p) dN_I/dX_k(p) to fe, given the weighted stresses Sw[3i + k][p] =
/// w_p S_ik(p) (w_p = Gauss weight x det J): T_id = Sw_ik J^{-1}_dk/8 at each point, then each
/// edge line's two points summed and taken back to the edges (bilinear_at_points, transposed).
template <class T>
inline void add_point_forces(const T Sw[9][8], const T Q[9][8], T fe[24]) {
  for (int i = 0; i < 3; ++i) {
    T E[3][4];  // edge values along each direction
    for (int d = 0; d < 3; ++d) {
      T Tp[8];
      for (int p = 0; p < 8; ++p)
        Tp[p] = Sw[3 * i][p] * Q[3 * d][p] + Sw[3 * i + 1][p] * Q[3 * d + 1][p] + Sw[3 * i + 2][p] * Q[3 * d + 2][p];
      T line[4];
      for (int e = 0; e < 4; ++e) line[e] = Tp[edges::minus_node[d][e]] + Tp[edges::plus_node[d][e]];
      edges::bilinear_at_points(line, E[d]);
    }
    for (int I = 0; I < 8; ++I)
      fe[8 * i + I] += edges::sign_of[0][I] * E[0][edges::edge_of[0][I]] + edges::sign_of[1][I] * E[1][edges::edge_of[1][I]] +
                       edges::sign_of[2][I] * E[2][edges::edge_of[2][I]];
  }
}

}  // namespace tribex::solver::hex8
