// SPDX-License-Identifier: MIT
#include "solver/hex8/internal_forces.hpp"

#include "solver/hex8/block_kernels.hpp"

namespace tribex::solver {

// The instruction-set files' entry points, with add_internal_forces's signature.
#ifdef TRIBEX_AVX2_KERNELS
namespace hex8::avx2 {
// avx2_kernels.cpp: four lanes
ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity, const double* coordinates,
                                  const double* u, const double* v, double* force, double dt, bool want_stress,
                                  bool want_stable_step);
}  // namespace hex8::avx2
#endif
#ifdef TRIBEX_AVX512_KERNELS
namespace hex8::avx512 {
// avx512_kernels.cpp: eight lanes, and four lanes with 32 registers
ElementPassTotals internal_forces(ElementBlock& block, const int* connectivity, const double* coordinates,
                                  const double* u, const double* v, double* force, double dt, bool want_stress,
                                  bool want_stable_step);
ElementPassTotals internal_forces_four_lanes(ElementBlock& block, const int* connectivity, const double* coordinates,
                                             const double* u, const double* v, double* force, double dt, bool want_stress,
                                             bool want_stable_step);
}  // namespace hex8::avx512
#endif

namespace {

KernelIsa cpu_isa() {
  __builtin_cpu_init();
#ifdef TRIBEX_AVX512_KERNELS
  // libgcc's test includes the OS's (XGETBV) enabling of the 512-bit register state
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) return KernelIsa::avx512;
#endif
#ifdef TRIBEX_AVX2_KERNELS
  if (__builtin_cpu_supports("avx2")) return KernelIsa::avx2;
#endif
  return KernelIsa::sse2;
}

int forced_lane_width = 0;
KernelIsa isa_limit = KernelIsa::avx512;

}  // namespace

KernelIsa element_isa() {
  static const KernelIsa cpu = cpu_isa();
  return cpu < isa_limit ? cpu : isa_limit;
}

void limit_element_isa(KernelIsa isa) { isa_limit = isa; }

int element_lane_width() {
  const KernelIsa isa = element_isa();
  const int widest = isa == KernelIsa::avx512 ? 8 : isa == KernelIsa::avx2 ? 4 : 2;
  return forced_lane_width > 0 && forced_lane_width <= widest ? forced_lane_width : widest;
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
  if (lanes == 4 && element_isa() == KernelIsa::avx512)
    return hex8::avx512::internal_forces_four_lanes(block, connectivity, coordinates, u, v, force, dt, want_stress,
                                                    want_stable_step);
#endif
#ifdef TRIBEX_AVX2_KERNELS
  if (lanes == 4)
    return hex8::avx2::internal_forces(block, connectivity, coordinates, u, v, force, dt, want_stress, want_stable_step);
#endif
  return hex8::block_internal_forces<materials::double2>(block, connectivity, coordinates, u, v, force, dt, want_stress,
                                                         want_stable_step);
}

}  // namespace tribex::solver
