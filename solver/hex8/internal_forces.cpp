// SPDX-License-Identifier: MIT
#include "solver/hex8/internal_forces.hpp"

#include "solver/hex8/fully_integrated.hpp"
#include "solver/hex8/mean_quadrature.hpp"

namespace tribex::solver {

#ifdef TRIBEX_AVX2_KERNELS
namespace hex8::avx2 {
// avx2_kernels.cpp
ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity, const double* u, const double* v,
                                  double* force, double dt, bool want_stress);
}  // namespace hex8::avx2
#endif

namespace {

int cpu_lane_width() {
#ifdef TRIBEX_AVX2_KERNELS
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2")) return 4;
#endif
  return 2;
}

int forced_lane_width = 0;

}  // namespace

int element_lane_width() {
  static const int cpu = cpu_lane_width();
  return forced_lane_width == 2 || (forced_lane_width == 4 && cpu == 4) ? forced_lane_width : cpu;
}

void set_element_lane_width(int lanes) { forced_lane_width = lanes; }

ElementPassTotals add_internal_forces(ElementBlock& block, const int* connectivity, const double* u,
                                      const double* v, double* force, double dt, bool want_stress) {
#ifdef TRIBEX_AVX2_KERNELS
  if (element_lane_width() == 4)
    return hex8::avx2::internal_forces(block, connectivity, u, v, force, dt, want_stress);
#endif
  return std::visit(
      [&](const auto& mat) {
        using materials::double2;
        if (block.formulation == inputs::ElementFormulation::mean_quadrature)
          return hex8::mean_quadrature_forces<double2>(mat, block, connectivity, u, v, force, dt, want_stress);
        return hex8::fully_integrated_forces<double2>(mat, block, connectivity, u, v, force, dt, want_stress);
      },
      block.material);
}

}  // namespace tribex::solver
