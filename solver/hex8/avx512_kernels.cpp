// SPDX-License-Identifier: MIT
// The element kernels at eight lanes (double8), the only file built with -mavx512f
// (solver/CMakeLists.txt), set up like avx2_kernels.cpp: everything inlined into the one entry
// point (flatten; CTest `avx2_kernels_isolated` checks this object too), and no fused multiply-add
// (-ffp-contract=off), so an element's results are bitwise those at four, two or one lane.
// add_internal_forces calls it only where the CPU (and the OS) has AVX-512F (element_lane_width()).
#ifdef __AVX512F__
#include "solver/hex8/fully_integrated.hpp"
#include "solver/hex8/mean_quadrature.hpp"

namespace tribex::solver::hex8::avx512 {

__attribute__((flatten)) ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity,
                                                          const double* coordinates, const double* u, const double* v, double* force, double dt,
                                                          bool want_stress, bool want_stable_step) {
  using materials::double8;
  return std::visit(
      [&](const auto& mat) {
        if (block.formulation == inputs::ElementFormulation::mean_quadrature)
          return mean_quadrature_forces<double8>(mat, block, connectivity, u, v, force, dt, want_stress, want_stable_step);
        return fully_integrated_forces<double8>(mat, block, connectivity, coordinates, u, v, force, dt, want_stress,
                                                want_stable_step);
      },
      block.material);
}

}  // namespace tribex::solver::hex8::avx512
#endif
