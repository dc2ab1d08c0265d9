// SPDX-License-Identifier: MIT
// Uniform-strain (mean-quadrature) hex8 of Flanagan & Belytschko (1981), total-Lagrangian form,
// with orthogonal hourglass control and bulk viscosity (physics.md 1.5, 2.1, 2.2):
//   H_ij   = (1/V0) u_iI B0_jI                         displacement gradient, F = I + H
//   S      = material.force_stress(H)                  Cauchy (small strain) or first Piola (finite)
//   edot_v = (1/V0) v_iI B0_iI                          volumetric strain rate (reference operator)
//   q      = -b1 rho c L edot_v + rho (b2 L)^2 edot_v^2 [edot_v < 0]
//   f_iI  -= (S_ij - q delta_ij) B0_jI
//   h_ia   = u_iJ gamma_aJ,  g_ia = v_iJ gamma_aJ
//   f_iI  -= (k_hg h_ia + c_hg g_ia) gamma_aI         hourglass stiffness and viscosity
// The hourglass stiffness is written in total form, k_hg gamma gamma^T u, which equals the
// incremental form of physics.md 2.2 for a constant coefficient; because gamma is orthogonal to
// every linear field of the reference coordinates, rigid rotations (u = (R - I) X) produce no
// hourglass force at any angle.
#pragma once

#include <cmath>

#include "solver/element_block.hpp"

namespace tribex::solver::hex8 {

template <class Material>
ElementPassTotals mean_quadrature_forces(const Material& mat, ElementBlock& blk, const int* conn,
                                         const double* u, const double* v, double* force,
                                         bool want_stress) {
  ElementPassTotals totals;
  const double b1 = blk.linear_bulk_viscosity, b2 = blk.quadratic_bulk_viscosity;
  const double rho = mat.density, rho_c = blk.rho_c;
  for (int e = 0; e < blk.count; ++e) {
    const int* nodes = conn + 8 * (blk.first_element + e);
    const double* B = &blk.B0[24 * e];
    const double* gam = &blk.gamma[32 * e];
    double ue[24], ve[24];
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) {
        ue[8 * i + I] = u[3 * nodes[I] + i];
        ve[8 * i + I] = v[3 * nodes[I] + i];
      }
    const double inv_v0 = 1.0 / blk.volume0[e];
    double H[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0.0;
        for (int I = 0; I < 8; ++I) s += ue[8 * i + I] * B[8 * j + I];
        H[3 * i + j] = s * inv_v0;
      }
    double edot = 0.0;
    for (int k = 0; k < 24; ++k) edot += ve[k] * B[k];
    edot *= inv_v0;
    double S[9];
    const double W = mat.force_stress(H, S);
    if (!std::isfinite(W)) {
      if (totals.first_inverted < 0) totals.first_inverted = blk.first_element + e;
      continue;
    }
    const double L = blk.length0[e];
    const double q = -b1 * rho_c * L * edot + (edot < 0.0 ? rho * (b2 * L) * (b2 * L) * edot * edot : 0.0);
    S[0] -= q;
    S[4] -= q;
    S[8] -= q;
    double fe[24];
    for (int i = 0; i < 3; ++i)
      for (int I = 0; I < 8; ++I)
        fe[8 * i + I] = S[3 * i] * B[I] + S[3 * i + 1] * B[8 + I] + S[3 * i + 2] * B[16 + I];
    // Hourglass.
    const double k = blk.hg_k[e], c = blk.hg_c[e];
    double hg_energy = 0.0, hg_power = 0.0;
    for (int a = 0; a < 4; ++a) {
      const double* ga = gam + 8 * a;
      for (int i = 0; i < 3; ++i) {
        double h = 0.0, gv = 0.0;
        for (int I = 0; I < 8; ++I) {
          h += ue[8 * i + I] * ga[I];
          gv += ve[8 * i + I] * ga[I];
        }
        hg_energy += h * h;
        hg_power += gv * gv;
        const double r = k * h + c * gv;
        for (int I = 0; I < 8; ++I) fe[8 * i + I] += r * ga[I];
      }
    }
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) force[3 * nodes[I] + i] -= fe[8 * i + I];
    totals.strain_energy += W * blk.volume0[e];
    totals.hourglass_energy += 0.5 * k * hg_energy;
    totals.viscous_power += c * hg_power - q * edot * blk.volume0[e];
    if (want_stress) mat.cauchy_stress(H, &blk.stress[6 * e]);
  }
  return totals;
}

}  // namespace tribex::solver::hex8
