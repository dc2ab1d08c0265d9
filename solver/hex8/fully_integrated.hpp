// SPDX-License-Identifier: MIT
// Fully integrated hex8: 2x2x2 Gauss quadrature in total-Lagrangian form (docs/theory.md 2.3), no
// hourglass control needed. At each point g: H = u_iI dN_I/dX_j, S = material.force_stress(H),
// f_iI -= wdetJ_g S_ij dN_I/dX_j, the gradients and forces sum-factorised over the element's
// edges (sum_factorized.hpp). A material with state keeps it per point, interleaved like the
// operators: value k of point p of element e at lane_index(e, p state_size + k, 8 state_size).
// Elements run eight at a time per AVX-512 register, four per AVX2 register or two per SSE register
// (lanes.hpp), the tail four, two and one at a time, bitwise as they would in a full register. Bulk
// viscosity uses the element-mean volumetric rate (B0, as in the mean-quadrature element), which is
// adequate for the damping role it has here. Locks volumetrically as nu -> 0.5 (use mean
// quadrature there).
#pragma once

#include "materials/lanes.hpp"
#include "solver/element_block.hpp"
#include "solver/hex8/element_stable_step.hpp"
#include "solver/hex8/internal_forces.hpp"
#include "solver/hex8/node_lanes.hpp"
#include "solver/hex8/sum_factorized.hpp"

namespace tribex::solver::hex8 {

/// Elements e .. e + lane_count<T> - 1 of the block (e a multiple of the lane count).
template <class T, class Material>
void fully_integrated_lanes(const Material& mat, ElementBlock& blk, int e, const int* conn, const double* X,
                            const double* u, const double* v, double* force, double dt, bool want_stress, bool want_stable_step,
                            ElementPassTotals& totals) {
  constexpr int ns = Material::state_size;
  using materials::lane;
  constexpr int n = materials::lane_count<T>;
  const int* nodes[n];
  for (int l = 0; l < n; ++l) nodes[l] = conn + 8 * (blk.first_element + e + l);
  T ue[24], ve[24], Xe[24];
  gather_nodal(u, nodes, ue);
  gather_nodal(v, nodes, ve);
  gather_nodal(X, nodes, Xe);
  // Formed here rather than read: 24 coordinates against 80 stored numbers per element, which made
  // the kernel memory-bound (docs/measurements/2026-11-27-bench-element-kernels.md, "Reference geometry rebuilt")
  T Q[9][8], w[8];
  inverse_jacobians_at_points(Xe, Q, w);

  // Bulk viscosity (docs/theory.md 1.5): a pressure q = -b1 rho c L edot + rho (b2 L)^2 min(edot, 0)^2
  // from the element's mean volumetric rate edot = B0_iI v_iI / V. Its force -q B0_iI is added
  // through the point stresses (S - q I at each point), since B0 = sum_p wdetJ_p dN/dX(p).
  // e is a multiple of the lane count: lane l of an interleaved record is element e + l (element_block.hpp)
  const T V = materials::load_lanes<T>(&blk.volume0[e]);
  const T L = materials::load_lanes<T>(&blk.length0[e]);
  T B0[24];
  for (int k = 0; k < 24; ++k) B0[k] = load_record<T>(blk.B0, e, k, 24);
  T edot{};
  for (int k = 0; k < 24; ++k) edot += ve[k] * B0[k];
  edot /= V;
  const T compression = materials::negative_part(edot);
  const T q = -blk.linear_bulk_viscosity * blk.rho_c * L * edot +
              mat.density * (blk.quadratic_bulk_viscosity * L) * (blk.quadratic_bulk_viscosity * L) * compression * compression;
  const T viscous_power = -q * edot * V;

  T G[3][3][8];
  reference_gradients_at_points(ue, G);
  T Sw[9][8];  // wdetJ_p (S - q I) at each point: the weight folded into the 9 stresses, not the 24 forces
  T energy{}, not_finite{}, plastic_work{};
  double stress_mean[n][6] = {};
  for (int p = 0; p < 8; ++p) {
    T H[9], S[9], dissipated;
    point_gradient(G, Q, p, H);
    T state[ns > 0 ? ns : 1];
    for (int k = 0; k < ns; ++k) state[k] = load_record<T>(blk.state, e, ns * p + k, 8 * ns);
    const T W = materials::point_stress(mat, H, state, dt, S, dissipated);
    for (int k = 0; k < ns; ++k) store_record(blk.state, e, ns * p + k, 8 * ns, state[k]);
    not_finite += 0.0 * W;  // NaN in a lane once any of its W is NaN or inf (inverted element)
    energy += w[p] * W;
    if constexpr (Material::dissipates) plastic_work += w[p] * dissipated;
    S[0] -= q;
    S[4] -= q;
    S[8] -= q;
    for (int k = 0; k < 9; ++k) Sw[k][p] = w[p] * S[k];
    if (want_stress)
      for (int l = 0; l < n; ++l) {
        double Hl[9], state_l[ns > 0 ? ns : 1], sv[6];
        for (int k = 0; k < 9; ++k) Hl[k] = lane(H[k], l);
        for (int k = 0; k < ns; ++k) state_l[k] = lane(state[k], l);
        materials::point_cauchy_stress(mat, Hl, state_l, sv);
        for (int k = 0; k < 6; ++k) stress_mean[l][k] += lane(w[p], l) * sv[k];
      }
  }
  T fe[24] = {};
  add_point_forces(Sw, Q, fe);

  if (want_stable_step) {
    // the element's mean gradient, as the mean-quadrature kernel forms it (element_stable_step.hpp)
    const T inv_v0 = 1.0 / V;
    T H_mean[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        T sum{};
        for (int I = 0; I < 8; ++I) sum += ue[8 * i + I] * B0[8 * j + I];
        H_mean[3 * i + j] = sum * inv_v0;
      }
    add_stable_steps(mat, blk, e, H_mean, B0, totals.stable);
  }

  unsigned finite_lanes = 0;
  for (int l = 0; l < n; ++l)
    if (lane(not_finite, l) == 0.0)  // not NaN
      finite_lanes |= 1u << l;
    else if (totals.first_inverted < 0)
      totals.first_inverted = blk.first_element + e + l;
  subtract_nodal(force, nodes, fe, finite_lanes);
  if (blk.viscous_force) [[unlikely]] {  // the bulk viscosity's part of fe, -q B0 (the ledger's right half)
    T fv[24];
    for (int k = 0; k < 24; ++k) fv[k] = -q * B0[k];
    subtract_nodal(blk.viscous_force, nodes, fv, finite_lanes);
  }
  for (int l = 0; l < n; ++l) {
    if (!(finite_lanes >> l & 1u)) continue;
    totals.strain_energy += lane(energy, l);
    totals.viscous_power += lane(viscous_power, l);
    if constexpr (Material::dissipates) totals.plastic_work += lane(plastic_work, l);
    if (want_stress)
      for (int k = 0; k < 6; ++k) blk.stress[6 * (e + l) + k] = stress_mean[l][k] / blk.volume0[e + l];
  }
}

/// The block at lane width T (double2, double4 or double8), the tail four (after eight), two and one at a time.
template <class T, class Material>
ElementPassTotals fully_integrated_forces(const Material& mat, ElementBlock& blk, const int* conn,
                                          const double* X, const double* u, const double* v, double* force, double dt,
                                          bool want_stress, bool want_stable_step) {
  ElementPassTotals totals;
  constexpr int n = materials::lane_count<T>;
  int e = 0;
  for (; e + n <= blk.count; e += n) fully_integrated_lanes<T>(mat, blk, e, conn, X, u, v, force, dt, want_stress, want_stable_step, totals);
#ifdef __AVX512F__
  if constexpr (n > 4)
    for (; e + 4 <= blk.count; e += 4)
      fully_integrated_lanes<materials::double4>(mat, blk, e, conn, X, u, v, force, dt, want_stress, want_stable_step, totals);
#endif
  if constexpr (n > 2)
    for (; e + 2 <= blk.count; e += 2)
      fully_integrated_lanes<materials::double2>(mat, blk, e, conn, X, u, v, force, dt, want_stress, want_stable_step, totals);
  for (; e < blk.count; ++e) fully_integrated_lanes<double>(mat, blk, e, conn, X, u, v, force, dt, want_stress, want_stable_step, totals);
  return totals;
}

}  // namespace tribex::solver::hex8
