// SPDX-License-Identifier: MIT
#include "solver/hex8/internal_forces.hpp"

#include "solver/hex8/fully_integrated.hpp"
#include "solver/hex8/mean_quadrature.hpp"

namespace tribex::solver {

ElementPassTotals add_internal_forces(ElementBlock& block, const int* connectivity, const double* u,
                                      const double* v, double* force, double dt, bool want_stress) {
  return std::visit(
      [&](const auto& mat) {
        if (block.formulation == inputs::ElementFormulation::mean_quadrature)
          return hex8::mean_quadrature_forces(mat, block, connectivity, u, v, force, dt, want_stress);
        return hex8::fully_integrated_forces(mat, block, connectivity, u, v, force, dt, want_stress);
      },
      block.material);
}

}  // namespace tribex::solver
