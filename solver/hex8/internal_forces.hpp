// SPDX-License-Identifier: MIT
// The internal-force pass over one element block: the entry point the integrator calls, dispatched
// once per block to the kernel of its formulation and material (mean_quadrature.hpp,
// fully_integrated.hpp). The block's data (solver/element_block.hpp) knows nothing of the kernels.
#pragma once

#include "solver/element_block.hpp"
#include "solver/hex8/element_stable_step.hpp"

namespace tribex::solver {

/// What one internal-force pass over a block adds up.
struct ElementPassTotals {
  double strain_energy = 0.0;     // sum V0 W (J)
  double hourglass_energy = 0.0;  // stored hourglass energy (J)
  double viscous_power = 0.0;     // hourglass viscosity + bulk viscosity dissipation rate (W)
  double plastic_work = 0.0;      // work the material updates of this pass dissipated (J)
  int first_inverted = -1;        // global element index of the first inverted element, or -1
  hex8::StableStepMin stable;     // when asked for: the block's stable step at this u (stable_time_step.hpp)
};

/// The instruction sets the element kernels are built for, in order (avx512: AVX-512F with VL).
enum class KernelIsa { sse2, avx2, avx512 };
/// The best of them the CPU has, or the limit set by limit_element_isa where that is lower.
KernelIsa element_isa();
/// Run the kernels with at most this instruction set (tests and `tribex bench block --isa`; the
/// default, avx512, leaves the CPU's best). The results are bitwise the same with every one.
void limit_element_isa(KernelIsa isa);

/// The widest element batch the instruction set runs: 8 (avx512), 4 (avx2) or 2 (sse2, every
/// x86-64); or the width forced by set_element_lane_width. The results are bitwise the same at
/// every width (mean_quadrature.hpp).
int element_lane_width();
/// Elements per kernel call for a block of this formulation: the forced width, else the CPU's
/// widest but at most 4 for mean quadrature, whose eight-lane kernel measured about 10 % slower
/// than the four-lane one at 40^3 on an AMD EPYC and an Intel Xeon with AVX-512 (while the fully
/// integrated one gained 13-16 %: docs/measurements/2026-11-25-bench-simd-element-batches.md, "Eight lanes";
/// docs/measurements/2026-11-27-bench-element-kernels.md, "Thirty-two registers").
int element_lane_width(inputs::ElementFormulation formulation);
/// Force the width (2, 4 or 8; a width above the CPU's widest gives its widest; 0: the default
/// above): tests and `tribex bench block --lanes`.
void set_element_lane_width(int lanes);

/// Internal forces of one block, subtracted from `force` [node][3]:
///   f_iI = S_ij B0_jI (mean quadrature) or sum_g wdetJ_g S_ij dN_I/dX_j(g) (fully integrated),
/// S from the material (Cauchy/first Piola), minus the bulk-viscosity pressure q (docs/theory.md 1.5),
/// plus Flanagan-Belytschko hourglass forces (mean quadrature, docs/theory.md 2.2).
/// coordinates [node][3] reference coordinates (the fully integrated kernel forms its point
/// geometry from them), u [node][3] displacement at t^{n+1}, v [node][3] velocity at t^{n+1/2}.
/// The material state goes from t^n to t^{n+1} (dt = t^{n+1} - t^n). When `want_stress` the block's
/// stress buffer is filled (Cauchy stress, element mean). When `want_stable_step` the pass also
/// returns the block's stable step at u in `stable`, bitwise what compute_stable_time_step gives
/// (the estimate folded into a pass that already has the element's gradient).
ElementPassTotals add_internal_forces(ElementBlock& block, const int* connectivity, const double* coordinates,
                                      const double* u, const double* v, double* force, double dt, bool want_stress,
                                      bool want_stable_step = false);

}  // namespace tribex::solver
