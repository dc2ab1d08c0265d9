// SPDX-License-Identifier: MIT
// Uniform-strain (mean-quadrature) hex8 of Flanagan & Belytschko (1981), total-Lagrangian form,
// with orthogonal hourglass control and bulk viscosity (docs/theory.md 1.5, 2.1, 2.2):
//   H_ij   = (1/V0) u_iI B0_jI                         displacement gradient, F = I + H
//   S      = point_stress(material, H, state)         Cauchy (small strain) or first Piola (finite);
//                                                      the point's state (if any) goes n -> n+1
//   edot_v = (1/V0) v_iI B0_iI                          volumetric strain rate (reference operator)
//   q      = -b1 rho c L edot_v + rho (b2 L)^2 edot_v^2 [edot_v < 0]
//   f_iI  -= (S_ij - q delta_ij) B0_jI
//   h_ia   = u_iJ gamma_aJ,  g_ia = v_iJ gamma_aJ
//   f_iI  -= (k_hg h_ia + c_hg g_ia) gamma_aI         hourglass stiffness and viscosity
// The hourglass stiffness is written in total form, k_hg gamma gamma^T u, which equals the
// incremental form of docs/theory.md 2.2 for a constant coefficient; because gamma is orthogonal to
// every linear field of the reference coordinates, rigid rotations (u = (R - I) X) produce no
// hourglass force at any angle.
#pragma once

#include <cmath>

#include "solver/element_block.hpp"
#include "solver/hex8/internal_forces.hpp"

namespace tribex::solver::hex8 {

template <class Material, bool HourglassViscosity>
ElementPassTotals mean_quadrature_forces_impl(const Material& mat, ElementBlock& blk, const int* conn,
                                              const double* u, const double* v, double* force, double dt,
                                              bool want_stress) {
  constexpr int ns = Material::state_size;  // one material point per element: [e][ns]
  ElementPassTotals totals;
  double* state = blk.state.data();
  const double b1 = blk.linear_bulk_viscosity, b2 = blk.quadratic_bulk_viscosity;
  const double rho = mat.density, rho_c = blk.rho_c;
  const double* B0 = blk.B0.data();
  const double* G0 = blk.gamma.data();
  for (int e = 0; e < blk.count; ++e) {
    const int* nodes = conn + 8 * (blk.first_element + e);
    const double* B = B0 + 24 * e;
    const double* gam = G0 + 32 * e;
    // Gather [component][node] so that every sum below runs over 8 contiguous values.
    double ue[24], ve[24];
    for (int I = 0; I < 8; ++I) {
      const double* un = u + 3 * nodes[I];
      const double* vn = v + 3 * nodes[I];
      ue[I] = un[0];
      ue[8 + I] = un[1];
      ue[16 + I] = un[2];
      ve[I] = vn[0];
      ve[8 + I] = vn[1];
      ve[16 + I] = vn[2];
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
    double S[9], dissipated;
    const double W = materials::point_stress(mat, H, state + ns * e, dt, S, dissipated);
    if (!std::isfinite(W)) {
      if (totals.first_inverted < 0) totals.first_inverted = blk.first_element + e;
      continue;
    }
    const double L = blk.length0[e];
    const double q = -b1 * rho_c * L * edot + (edot < 0.0 ? rho * (b2 * L) * (b2 * L) * edot * edot : 0.0);
    S[0] -= q;
    S[4] -= q;
    S[8] -= q;
    // Hourglass generalized displacements h_ia = u_iJ gamma_aJ (and rates g_ia = v_iJ gamma_aJ).
    const double k = blk.hg_k[e];
    double r[12], hg_energy = 0.0, hg_power = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) {
        double h = 0.0;
        for (int J = 0; J < 8; ++J) h += ue[8 * i + J] * gam[8 * a + J];
        hg_energy += h * h;
        r[3 * a + i] = k * h;
        if constexpr (HourglassViscosity) {
          double g = 0.0;
          for (int J = 0; J < 8; ++J) g += ve[8 * i + J] * gam[8 * a + J];
          hg_power += g * g;
          r[3 * a + i] += blk.hg_c[e] * g;
        }
      }
    // f_iI = S_ij B_jI + r_ia gamma_aI, subtracted from the nodal forces.
    for (int I = 0; I < 8; ++I) {
      double f[3];
      for (int i = 0; i < 3; ++i)
        f[i] = S[3 * i] * B[I] + S[3 * i + 1] * B[8 + I] + S[3 * i + 2] * B[16 + I] + r[i] * gam[I] +
               r[3 + i] * gam[8 + I] + r[6 + i] * gam[16 + I] + r[9 + i] * gam[24 + I];
      double* fn = force + 3 * nodes[I];
      fn[0] -= f[0];
      fn[1] -= f[1];
      fn[2] -= f[2];
    }
    totals.strain_energy += W * blk.volume0[e];
    totals.hourglass_energy += 0.5 * k * hg_energy;
    totals.viscous_power -= q * edot * blk.volume0[e];
    if constexpr (HourglassViscosity) totals.viscous_power += blk.hg_c[e] * hg_power;
    if constexpr (Material::dissipates) totals.plastic_work += dissipated * blk.volume0[e];
    if (want_stress) materials::point_cauchy_stress(mat, H, state + ns * e, &blk.stress[6 * e]);
  }
  return totals;
}

template <class Material>
ElementPassTotals mean_quadrature_forces(const Material& mat, ElementBlock& blk, const int* conn,
                                         const double* u, const double* v, double* force, double dt,
                                         bool want_stress) {
  if (blk.hourglass_viscosity > 0.0)
    return mean_quadrature_forces_impl<Material, true>(mat, blk, conn, u, v, force, dt, want_stress);
  return mean_quadrature_forces_impl<Material, false>(mat, blk, conn, u, v, force, dt, want_stress);
}

}  // namespace tribex::solver::hex8
