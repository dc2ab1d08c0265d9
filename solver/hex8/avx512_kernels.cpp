// SPDX-License-Identifier: MIT
// The element kernels on AVX-512 CPUs, the only file built with -mavx512f -mavx512vl
// (solver/CMakeLists.txt), set up like avx2_kernels.cpp: everything inlined into each entry point
// (flatten; CTest `avx2_kernels_isolated` checks this object too), and no fused multiply-add
// (-ffp-contract=off), so an element's results are bitwise those at four, two or one lane.
//   internal_forces             eight lanes (double8 in 512-bit registers)
//   internal_forces_four_lanes  four lanes (double4), as avx2_kernels.cpp but with AVX-512VL's 32 vector
//                               registers instead of AVX2's 16: the mean-quadrature kernel keeps 72
//                               vectors of nodal values and gradient operator, and with fewer of them
//                               spilled the block ran in 0.93x the time
//                               (docs/measurements/2026-11-27-bench-element-kernels.md, "Thirty-two registers")
// add_internal_forces calls them only where the CPU (and the OS) has AVX-512F and VL (element_isa()).
#if defined(__AVX512F__) && defined(__AVX512VL__)
#include "solver/hex8/block_kernels.hpp"

namespace tribex::solver::hex8::avx512 {

__attribute__((flatten)) ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity,
                                                          const double* coordinates, const double* u, const double* v,
                                                          double* force, double dt, bool want_stress,
                                                          bool want_stable_step) {
  return block_internal_forces<materials::double8>(block, connectivity, coordinates, u, v, force, dt, want_stress,
                                                   want_stable_step);
}

__attribute__((flatten)) ElementPassTotals internal_forces_four_lanes(ElementBlock& block, const int* connectivity,
                                                                     const double* coordinates, const double* u,
                                                                     const double* v, double* force, double dt,
                                                                     bool want_stress, bool want_stable_step) {
  return block_internal_forces<materials::double4>(block, connectivity, coordinates, u, v, force, dt, want_stress,
                                                   want_stable_step);
}

}  // namespace tribex::solver::hex8::avx512
#endif
