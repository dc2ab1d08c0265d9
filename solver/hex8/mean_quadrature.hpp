// SPDX-License-Identifier: MIT
// Uniform-strain (mean-quadrature) hex8 of Flanagan & Belytschko (1981), total-Lagrangian form,
// with orthogonal hourglass control and bulk viscosity (docs/theory.md 1.5, 2.1, 2.2):
//   s_ij   = u_iI B0_jI,  H_ij = s_ij / V0             displacement gradient, F = I + H
//   S      = point_stress(material, H, state)         Cauchy (small strain) or first Piola (finite);
//                                                      the point's state (if any) goes n -> n+1
//   edot_v = (1/V0) v_iI B0_iI                          volumetric strain rate (reference operator)
//   q      = -b1 rho c L edot_v + rho (b2 L)^2 edot_v^2 [edot_v < 0]
//   gamma_aI = Gamma_aI - c_aj B0_jI                   hourglass vectors, factored (geometry.hpp)
//   h_ia   = u_iJ gamma_aJ = u_iJ Gamma_aJ - c_aj s_ij  (and rates g_ia from v likewise)
//   r_ia   = k_hg h_ia + c_hg g_ia                      hourglass stiffness and viscosity
//   f_iI  -= (S_ij - q delta_ij - r_ia c_aj) B0_jI + r_ia Gamma_aI
// The hourglass stiffness is written in total form, k_hg gamma gamma^T u, which equals the
// incremental form of docs/theory.md 2.2 for a constant coefficient; because gamma is orthogonal to
// every linear field of the reference coordinates, rigid rotations (u = (R - I) X) produce no
// hourglass force at any angle.
//
// Elements run 1, 2, 4 or 8 at a time (T = double, double2, double4, double8: materials/lanes.hpp), element
// data interleaved by element (element_block.hpp). Every lane does the same IEEE operations in the
// same order, and the totals and nodal forces are added lane by lane in element order, so the
// results are bitwise the same at every lane width (tests/solver/element_lanes_test.cpp).
#pragma once

#include <cmath>

#include "materials/lanes.hpp"
#include "solver/element_block.hpp"
#include "solver/hex8/element_stable_step.hpp"
#include "solver/hex8/geometry.hpp"
#include "solver/hex8/internal_forces.hpp"
#include "solver/hex8/node_lanes.hpp"

namespace tribex::solver::hex8 {

/// g_a = Gamma_aJ x_J for the 4 hourglass base vectors (geometry.hpp hourglass_base), in adds and
/// subtracts: Gamma_0 = (p01 - p23) - (p45 - p67), Gamma_1 = (m01 - m23) - (m45 - m67),
/// Gamma_2 = (m01 + m23) + (m45 + m67), Gamma_3 = (m45 + m67) - (m01 + m23), with pIJ = x_I + x_J
/// and mIJ = x_I - x_J.
template <class T>
inline void hourglass_base_sums(const T x[8], T g[4]) {
  const T p01 = x[0] + x[1], p23 = x[2] + x[3], p45 = x[4] + x[5], p67 = x[6] + x[7];
  const T m01 = x[0] - x[1], m23 = x[2] - x[3], m45 = x[4] - x[5], m67 = x[6] - x[7];
  g[0] = (p01 - p23) - (p45 - p67);
  g[1] = (m01 - m23) - (m45 - m67);
  g[2] = (m01 + m23) + (m45 + m67);
  g[3] = (m45 + m67) - (m01 + m23);
}

/// f_I = r_a Gamma_aI (the transpose of hourglass_base_sums) for the 4 modes' r_a.
template <class T>
inline void hourglass_base_combinations(const T r0, const T r1, const T r2, const T r3, T f[8]) {
  // columns of Gamma come in pairs (I, I + 1) that share r_0 and differ in the sign of the rest
  const T a = r1 + r2 - r3, b = r1 - r2 + r3, c = r1 - r2 - r3, d = r1 + r2 + r3;
  f[0] = r0 + a;
  f[1] = r0 - a;
  f[2] = -r0 - b;
  f[3] = -r0 + b;
  f[4] = -r0 - c;
  f[5] = -r0 + c;
  f[6] = r0 + d;
  f[7] = r0 - d;
}

/// The finite lanes' shares of the block's totals (in element order, so that a block's total is a sum
/// over its elements in order) and, on output steps, their Cauchy stresses.
template <class T, class Material, bool HourglassViscosity>
inline void add_lane_totals(const Material& mat, ElementBlock& blk, int e, unsigned finite_lanes, const T& strain_energy,
                            const T& viscous_power, const T& k_hg, const T& hg_energy, const T& hg_power,
                            const T& dissipated, const T H[9], const T* state, bool want_stress, ElementPassTotals& totals) {
  using materials::lane;
  constexpr int n = materials::lane_count<T>;
  constexpr int ns = Material::state_size;
  for (int l = 0; l < n; ++l) {
    if (!(finite_lanes >> l & 1u)) continue;
    totals.strain_energy += lane(strain_energy, l);
    totals.hourglass_energy += 0.5 * lane(k_hg, l) * lane(hg_energy, l);
    // the element's dissipation rate first, so that a block's total is a sum over elements in order
    double element_power = lane(viscous_power, l);
    if constexpr (HourglassViscosity) element_power += blk.hg_c[e + l] * lane(hg_power, l);
    totals.viscous_power += element_power;
    if constexpr (Material::dissipates) totals.plastic_work += lane(dissipated, l) * blk.volume0[e + l];
    if (want_stress) {
      double Hl[9], state_l[ns > 0 ? ns : 1];
      for (int k = 0; k < 9; ++k) Hl[k] = lane(H[k], l);
      for (int k = 0; k < ns; ++k) state_l[k] = lane(state[k], l);
      materials::point_cauchy_stress(mat, Hl, state_l, &blk.stress[6 * (e + l)]);
    }
  }
}

/// The viscous part of an element's internal force, f_iI = P_ij B0_jI + r_ia Gamma_aI with q alone in
/// P and the hourglass viscosity's r_ia = c_hg g_ia (recomputed here from the rates w and the velocities,
/// so that the force pass keeps no copy when the ledger does not ask), into viscous_force [node][3]: the
/// energy ledger pairs it with v^{n+1/2} (docs/theory.md 1.3, `viscous dissipation = exact`).
template <class T, bool HourglassViscosity>
inline void add_viscous_forces(double* viscous_force, const int* const nodes[], const T& q, const T& hg_c,
                               const T ve[24], const T w[9], const T c[12], const T B[24], unsigned finite_lanes) {
  T rv[12] = {};
  if constexpr (HourglassViscosity)
    for (int i = 0; i < 3; ++i) {
      T vg[4];
      hourglass_base_sums(&ve[8 * i], vg);
      for (int a = 0; a < 4; ++a)
        rv[3 * a + i] = hg_c * (vg[a] - (c[3 * a] * w[3 * i] + c[3 * a + 1] * w[3 * i + 1] + c[3 * a + 2] * w[3 * i + 2]));
    }
  T fv[24];
  for (int i = 0; i < 3; ++i) {
    T P[3], hourglass_force[8] = {};
    for (int j = 0; j < 3; ++j) {
      P[j] = i == j ? -q : T{};
      if constexpr (HourglassViscosity)
        P[j] -= rv[i] * c[j] + rv[3 + i] * c[3 + j] + rv[6 + i] * c[6 + j] + rv[9 + i] * c[9 + j];
    }
    if constexpr (HourglassViscosity) hourglass_base_combinations(rv[i], rv[3 + i], rv[6 + i], rv[9 + i], hourglass_force);
    for (int I = 0; I < 8; ++I) fv[8 * i + I] = P[0] * B[I] + P[1] * B[8 + I] + P[2] * B[16 + I] + hourglass_force[I];
  }
  subtract_nodal(viscous_force, nodes, fv, finite_lanes);
}

/// Elements e .. e + lane_count<T> - 1 of a mean-quadrature block (e a multiple of the lane count).
template <class T, class Material, bool HourglassViscosity>
inline void mean_quadrature_lanes(const Material& mat, ElementBlock& blk, int e, const int* conn, const double* u,
                                  const double* v, double* force, double dt, bool want_stress,
                                  bool want_stable_step, ElementPassTotals& totals) {
  using materials::from_lanes;
  using materials::lane;
  using materials::load_lanes;
  constexpr int n = materials::lane_count<T>;
  constexpr int ns = Material::state_size;  // one material point per element: [e][ns]
  const int* nodes[n];
  for (int l = 0; l < n; ++l) nodes[l] = conn + 8 * (blk.first_element + e + l);
  // Gather [component][node] so that every sum below runs over 8 contiguous values.
  T ue[24], ve[24];
  gather_nodal(u, nodes, ue);
  gather_nodal(v, nodes, ve);
  T B[24];
  for (int k = 0; k < 24; ++k) B[k] = load_record<T>(blk.B0, e, k, 24);
  const T V = load_lanes<T>(&blk.volume0[e]);
  const T inv_v0 = 1.0 / V;
  T s[9], H[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T sum{};
      for (int I = 0; I < 8; ++I) sum += ue[8 * i + I] * B[8 * j + I];
      s[3 * i + j] = sum;
      H[3 * i + j] = sum * inv_v0;
    }
  T edot{};
  for (int k = 0; k < 24; ++k) edot += ve[k] * B[k];
  edot *= inv_v0;

  T state[ns > 0 ? ns : 1];
  for (int k = 0; k < ns; ++k) state[k] = from_lanes<T>([&](int l) { return blk.state[ns * (e + l) + k]; });
  T S[9], dissipated;
  const T W = materials::point_stress(mat, H, state, dt, S, dissipated);
  for (int k = 0; k < ns; ++k)
    for (int l = 0; l < n; ++l) blk.state[ns * (e + l) + k] = lane(state[k], l);

  const T L = load_lanes<T>(&blk.length0[e]);
  const double rho = mat.density, b1 = blk.linear_bulk_viscosity, b2 = blk.quadratic_bulk_viscosity;
  const T compression = materials::negative_part(edot);
  const T q = -b1 * blk.rho_c * L * edot + rho * (b2 * L) * (b2 * L) * compression * compression;

  // Hourglass generalized displacements h_ia and rates g_ia, from the B0 sums s (and w for v).
  T c[12];
  for (int k = 0; k < 12; ++k) c[k] = load_record<T>(blk.hg_coefficients, e, k, 12);
  T w[9];
  if constexpr (HourglassViscosity)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        T sum{};
        for (int I = 0; I < 8; ++I) sum += ve[8 * i + I] * B[8 * j + I];
        w[3 * i + j] = sum;
      }
  const T k_hg = load_lanes<T>(&blk.hg_k[e]);
  T r[12], hg_energy{}, hg_power{};
  for (int i = 0; i < 3; ++i) {
    T ug[4], vg[4];
    hourglass_base_sums(&ue[8 * i], ug);
    if constexpr (HourglassViscosity) hourglass_base_sums(&ve[8 * i], vg);
    for (int a = 0; a < 4; ++a) {
      const T h = ug[a] - (c[3 * a] * s[3 * i] + c[3 * a + 1] * s[3 * i + 1] + c[3 * a + 2] * s[3 * i + 2]);
      hg_energy += h * h;
      r[3 * a + i] = k_hg * h;
      if constexpr (HourglassViscosity) {
        const T g = vg[a] - (c[3 * a] * w[3 * i] + c[3 * a + 1] * w[3 * i + 1] + c[3 * a + 2] * w[3 * i + 2]);
        hg_power += g * g;
        r[3 * a + i] += load_lanes<T>(&blk.hg_c[e]) * g;
      }
    }
  }
  // P_ij = S_ij - q delta_ij - r_ia c_aj, then f_iI = P_ij B0_jI + r_ia Gamma_aI.
  T P[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      P[3 * i + j] = (i == j ? S[3 * i + j] - q : S[3 * i + j]) -
                     (r[i] * c[j] + r[3 + i] * c[3 + j] + r[6 + i] * c[6 + j] + r[9 + i] * c[9 + j]);
  T f[24];
  for (int i = 0; i < 3; ++i) {
    T hourglass_force[8];
    hourglass_base_combinations(r[i], r[3 + i], r[6 + i], r[9 + i], hourglass_force);
    for (int I = 0; I < 8; ++I)
      f[8 * i + I] = P[3 * i] * B[I] + P[3 * i + 1] * B[8 + I] + P[3 * i + 2] * B[16 + I] + hourglass_force[I];
  }

  unsigned finite_lanes = 0;
  for (int l = 0; l < n; ++l)
    if (std::isfinite(lane(W, l)))
      finite_lanes |= 1u << l;
    else if (totals.first_inverted < 0)
      totals.first_inverted = blk.first_element + e + l;
  subtract_nodal(force, nodes, f, finite_lanes);
  if (blk.viscous_force) [[unlikely]]
    add_viscous_forces<T, HourglassViscosity>(blk.viscous_force, nodes, q, load_lanes<T>(&blk.hg_c[e]), ve, w, c, B,
                                              finite_lanes);

  add_lane_totals<T, Material, HourglassViscosity>(mat, blk, e, finite_lanes, W * V, -q * edot * V, k_hg, hg_energy,
                                                   hg_power, dissipated, H, state, want_stress, totals);
  if (want_stable_step) add_stable_steps(mat, blk, e, H, B, totals.stable);
}

/// Elements [begin, count) of the block, `T` lanes at a time from `begin` (a multiple of the lane
/// count), the tail four (after eight), two and one at a time.
template <class T, class Material, bool HourglassViscosity>
void mean_quadrature_range(const Material& mat, ElementBlock& blk, int begin, const int* conn, const double* u,
                           const double* v, double* force, double dt, bool want_stress, bool want_stable_step,
                           ElementPassTotals& totals) {
  constexpr int n = materials::lane_count<T>;
  int e = begin;
  for (; e + n <= blk.count; e += n)
    mean_quadrature_lanes<T, Material, HourglassViscosity>(mat, blk, e, conn, u, v, force, dt, want_stress, want_stable_step, totals);
#ifdef __AVX512F__
  if constexpr (n > 4)
    for (; e + 4 <= blk.count; e += 4)
      mean_quadrature_lanes<materials::double4, Material, HourglassViscosity>(mat, blk, e, conn, u, v, force, dt,
                                                                             want_stress, want_stable_step, totals);
#endif
  if constexpr (n > 2)
    for (; e + 2 <= blk.count; e += 2)
      mean_quadrature_lanes<materials::double2, Material, HourglassViscosity>(mat, blk, e, conn, u, v, force, dt,
                                                                             want_stress, want_stable_step, totals);
  if constexpr (n > 1)
    for (; e < blk.count; ++e)
      mean_quadrature_lanes<double, Material, HourglassViscosity>(mat, blk, e, conn, u, v, force, dt, want_stress,
                                                                  want_stable_step, totals);
}

/// The block at lane width T.
template <class T, class Material>
ElementPassTotals mean_quadrature_forces(const Material& mat, ElementBlock& blk, const int* conn, const double* u,
                                         const double* v, double* force, double dt, bool want_stress,
                                         bool want_stable_step) {
  ElementPassTotals totals;
  if (blk.hourglass_viscosity > 0.0)
    mean_quadrature_range<T, Material, true>(mat, blk, 0, conn, u, v, force, dt, want_stress, want_stable_step, totals);
  else
    mean_quadrature_range<T, Material, false>(mat, blk, 0, conn, u, v, force, dt, want_stress, want_stable_step, totals);
  return totals;
}

}  // namespace tribex::solver::hex8
