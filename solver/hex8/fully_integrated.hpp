// SPDX-License-Identifier: MIT
// Fully integrated hex8: 2x2x2 Gauss quadrature in total-Lagrangian form (physics.md 2.3), no
// hourglass control needed. At each point g: H = u_iI dNdX_gjI, S = material.force_stress(H),
// f_iI -= wdetJ_g S_ij dNdX_gjI (the material called once for the 8 points: force_stress_points). Bulk viscosity uses the element-mean operator B0 (as in the
// mean-quadrature element), which is adequate for the damping role it has here. Locks
// volumetrically as nu -> 0.5 (use mean quadrature there).
#pragma once

#include <cmath>

#include "solver/element_block.hpp"

namespace tribex::solver::hex8 {

template <class Material>
ElementPassTotals fully_integrated_forces(const Material& mat, ElementBlock& blk, const int* conn,
                                          const double* u, const double* v, double* force,
                                          bool want_stress) {
  ElementPassTotals totals;
  const double b1 = blk.linear_bulk_viscosity, b2 = blk.quadratic_bulk_viscosity;
  const double rho = mat.density, rho_c = blk.rho_c;
  for (int e = 0; e < blk.count; ++e) {
    const int* nodes = conn + 8 * (blk.first_element + e);
    double ue[24], ve[24];
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) {
        ue[8 * i + I] = u[3 * nodes[I] + i];
        ve[8 * i + I] = v[3 * nodes[I] + i];
      }
    // Three passes over the 8 points, so that the material is evaluated for all of them at once
    // (force_stress_points: vectorised over the points, the 8 logs of the neo-Hookean model two per
    // call; tools/bench/README.md): displacement gradients, stresses, then forces.
    double H[9][8];  // [component][point]
    for (int g = 0; g < 8; ++g) {
      const double* D = &blk.dNdX[192 * e + 24 * g];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double s = 0.0;
          for (int I = 0; I < 8; ++I) s += ue[8 * i + I] * D[8 * j + I];
          H[3 * i + j][g] = s;
        }
    }
    double S[9][8], W[8];
    mat.force_stress_points(H, S, W);
    bool inverted = false;
    for (int g = 0; g < 8; ++g) inverted = inverted || !std::isfinite(W[g]);
    if (inverted) {
      if (totals.first_inverted < 0) totals.first_inverted = blk.first_element + e;
      continue;
    }
    const double* w = &blk.wdetJ[8 * e];
    double fe[24] = {};
    double energy = 0.0;
    for (int g = 0; g < 8; ++g) {
      const double* D = &blk.dNdX[192 * e + 24 * g];
      energy += w[g] * W[g];
      double Sw[9];
      for (int k = 0; k < 9; ++k) Sw[k] = w[g] * S[k][g];  // fold the weight into the 9 stresses, not the 24 forces
      for (int i = 0; i < 3; ++i)
        for (int I = 0; I < 8; ++I)
          fe[8 * i + I] += Sw[3 * i] * D[I] + Sw[3 * i + 1] * D[8 + I] + Sw[3 * i + 2] * D[16 + I];
    }
    double stress_mean[6] = {};
    if (want_stress)
      for (int g = 0; g < 8; ++g) {
        double Hg[9], sv[6];
        for (int k = 0; k < 9; ++k) Hg[k] = H[k][g];
        mat.cauchy_stress(Hg, sv);
        for (int k = 0; k < 6; ++k) stress_mean[k] += w[g] * sv[k];
      }
    const double* B = &blk.B0[24 * e];
    double edot = 0.0;
    for (int k = 0; k < 24; ++k) edot += ve[k] * B[k];
    edot /= blk.volume0[e];
    const double L = blk.length0[e];
    const double q = -b1 * rho_c * L * edot + (edot < 0.0 ? rho * (b2 * L) * (b2 * L) * edot * edot : 0.0);
    for (int k = 0; k < 24; ++k) fe[k] -= q * B[k];
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) force[3 * nodes[I] + i] -= fe[8 * i + I];
    totals.strain_energy += energy;
    totals.viscous_power += -q * edot * blk.volume0[e];
    if (want_stress)
      for (int k = 0; k < 6; ++k) blk.stress[6 * e + k] = stress_mean[k] / blk.volume0[e];
  }
  return totals;
}

}  // namespace tribex::solver::hex8
