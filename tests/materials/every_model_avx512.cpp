// SPDX-License-Identifier: MIT
// Every model at eight lanes (double8, lanes.hpp), built with -mavx512f -mno-fma -ffp-contract=off
// like solver/hex8/avx512_kernels.cpp (tests/materials/CMakeLists.txt); only the double8 code is made here.
#include "tests/materials/every_model_lanes.hpp"
#include "tests/materials/every_model_support.hpp"

namespace tribex::materials::every_model {

bool run_eight_lanes(const Material& m, int lanes, double* values) {
#ifdef __AVX512F__
  return run_material_at_width<double8>(m, lanes, values);
#endif
  return (void)m, (void)lanes, (void)values, false;  // not built for this width
}

}  // namespace tribex::materials::every_model
