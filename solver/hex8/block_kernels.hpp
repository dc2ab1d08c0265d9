// SPDX-License-Identifier: MIT
// One block's internal forces at lane width T (double2, double4, double8: materials/lanes.hpp),
// dispatched on the block's material and formulation: the body of every instruction-set entry point
// (internal_forces.cpp's SSE2 path, avx2_kernels.cpp, avx512_kernels.cpp), so that each of those says
// only which T it runs.
#pragma once

#include "solver/hex8/fully_integrated.hpp"
#include "solver/hex8/mean_quadrature.hpp"

namespace tribex::solver::hex8 {

template <class T>
inline ElementPassTotals block_internal_forces(ElementBlock& block, const int* connectivity, const double* coordinates,
                                               const double* u, const double* v, double* force, double dt,
                                               bool want_stress, bool want_stable_step) {
  return std::visit(
      [&](const auto& mat) {
        if (block.formulation == inputs::ElementFormulation::mean_quadrature)
          return mean_quadrature_forces<T>(mat, block, connectivity, u, v, force, dt, want_stress, want_stable_step);
        return fully_integrated_forces<T>(mat, block, connectivity, coordinates, u, v, force, dt, want_stress,
                                          want_stable_step);
      },
      block.material);
}

}  // namespace tribex::solver::hex8
