// SPDX-License-Identifier: MIT
#include "solver/hex8/internal_forces.hpp"

#include "solver/hex8/fully_integrated.hpp"
#include "solver/hex8/mean_quadrature.hpp"

namespace tribex::solver {

#ifdef TRIBEX_AVX2_KERNELS
namespace hex8::avx2 {
// avx2_kernels.cpp
ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity, const double* coordinates,
                                  const double* u, const double* v, double* force, double dt, bool want_stress,
                                  bool want_stable_step);
}  // namespace hex8::avx2
#endif
#ifdef TRIBEX_AVX512_KERNELS
namespace hex8::avx512 {
// avx512_kernels.cpp
ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity, const double* coordinates,
                                  const double* u, const double* v, double* force, double dt, bool want_stress,
                                  bool want_stable_step);
}  // namespace hex8::avx512
#endif

namespace {

int cpu_lane_width() {
  __builtin_cpu_init();
#ifdef TRIBEX_AVX512_KERNELS
  // libgcc's test includes the OS's (XGETBV) enabling of the 512-bit register state
  if (__builtin_cpu_supports("avx512f")) return 8;
#endif
#ifdef TRIBEX_AVX2_KERNELS
  if (__builtin_cpu_supports("avx2")) return 4;
#endif
  return 2;
}

int forced_lane_width = 0;

}  // namespace

int element_lane_width() {
  static const int cpu = cpu_lane_width();
  return forced_lane_width > 0 && forced_lane_width <= cpu ? forced_lane_width : cpu;
}

int element_lane_width(inputs::ElementFormulation formulation) {
  const int widest = element_lane_width();
  if (forced_lane_width > 0 || formulation != inputs::ElementFormulation::mean_quadrature) return widest;
  return widest < 4 ? widest : 4;
}

void set_element_lane_width(int lanes) { forced_lane_width = lanes; }

ElementPassTotals add_internal_forces(ElementBlock& block, const int* connectivity, const double* coordinates,
                                      const double* u, const double* v, double* force, double dt, bool want_stress,
                                      bool want_stable_step) {
  const int lanes = element_lane_width(block.formulation);
#ifdef TRIBEX_AVX512_KERNELS
  if (lanes == 8)
    return hex8::avx512::internal_forces(block, connectivity, coordinates, u, v, force, dt, want_stress, want_stable_step);
#endif
#ifdef TRIBEX_AVX2_KERNELS
  if (lanes == 4)
    return hex8::avx2::internal_forces(block, connectivity, coordinates, u, v, force, dt, want_stress, want_stable_step);
#endif
  return std::visit(
      [&](const auto& mat) {
        using materials::double2;
        if (block.formulation == inputs::ElementFormulation::mean_quadrature)
          return hex8::mean_quadrature_forces<double2>(mat, block, connectivity, u, v, force, dt, want_stress,
                                                              want_stable_step);
        return hex8::fully_integrated_forces<double2>(mat, block, connectivity, coordinates, u, v, force, dt, want_stress,
                                                              want_stable_step);
      },
      block.material);
}

}  // namespace tribex::solver
