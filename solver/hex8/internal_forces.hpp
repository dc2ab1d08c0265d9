// SPDX-License-Identifier: MIT
// The internal-force pass over one element block: the entry point the integrator calls, dispatched
// once per block to the kernel of its formulation and material (mean_quadrature.hpp,
// fully_integrated.hpp). The block's data (solver/element_block.hpp) knows nothing of the kernels.
#pragma once

#include "solver/element_block.hpp"

namespace tribex::solver {

/// What one internal-force pass over a block adds up.
struct ElementPassTotals {
  double strain_energy = 0.0;     // sum V0 W (J)
  double hourglass_energy = 0.0;  // stored hourglass energy (J)
  double viscous_power = 0.0;     // hourglass viscosity + bulk viscosity dissipation rate (W)
  double plastic_work = 0.0;      // work the material updates of this pass dissipated (J)
  int first_inverted = -1;        // global element index of the first inverted element, or -1
};

/// Internal forces of one block, subtracted from `force` [node][3]:
///   f_iI = S_ij B0_jI (mean quadrature) or sum_g wdetJ_g S_ij dN_I/dX_j(g) (fully integrated),
/// S from the material (Cauchy/first Piola), minus the bulk-viscosity pressure q (docs/theory.md 1.5),
/// plus Flanagan-Belytschko hourglass forces (mean quadrature, docs/theory.md 2.2).
/// u [node][3] displacement at t^{n+1}, v [node][3] velocity at t^{n+1/2}.
/// The material state goes from t^n to t^{n+1} (dt = t^{n+1} - t^n). When `want_stress` the block's
/// stress buffer is filled (Cauchy stress, element mean).
/// Elements per kernel call: 4 (AVX2) where the CPU has AVX2, else 2 (SSE2, every x86-64). The
/// results are bitwise the same at either width (mean_quadrature.hpp).
int element_lane_width();
/// Force the width (2 or 4; 4 only where the CPU has AVX2; 0: the CPU's best): tests and
/// `tribex bench block --lanes`.
void set_element_lane_width(int lanes);

ElementPassTotals add_internal_forces(ElementBlock& block, const int* connectivity, const double* u,
                                      const double* v, double* force, double dt, bool want_stress);

}  // namespace tribex::solver
