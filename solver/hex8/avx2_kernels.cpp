// SPDX-License-Identifier: MIT
// The element kernels at four lanes (double4), the only file built with -mavx2 (solver/CMakeLists.txt).
// Everything it calls is inlined into the one entry point (flatten), so the object defines no
// inline function that another object also defines: no AVX code can stand in for the baseline
// code of a shared inline function (CTest `avx2_kernels_isolated` checks the object's symbols).
// add_internal_forces calls it where the CPU has AVX2 but not AVX-512 (element_isa()).
#ifdef __AVX2__
#include "solver/hex8/block_kernels.hpp"

namespace tribex::solver::hex8::avx2 {

__attribute__((flatten)) ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity,
                                                          const double* coordinates, const double* u, const double* v,
                                                          double* force, double dt, bool want_stress,
                                                          bool want_stable_step) {
  return block_internal_forces<materials::double4>(block, connectivity, coordinates, u, v, force, dt, want_stress,
                                                   want_stable_step);
}

}  // namespace tribex::solver::hex8::avx2
#endif
