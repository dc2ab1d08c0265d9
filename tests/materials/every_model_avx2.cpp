// SPDX-License-Identifier: MIT
// Every model at four lanes (double4, lanes.hpp), built with -mavx2 -mno-fma like
// solver/hex8/avx2_kernels.cpp (tests/materials/CMakeLists.txt); only the double4 code is made here.
#include "tests/materials/every_model_lanes.hpp"
#include "tests/materials/every_model_support.hpp"

namespace tribex::materials::every_model {

bool run_four_lanes(const Material& m, int lanes, double* values) {
#ifdef __AVX2__
  return run_material_at_width<double4>(m, lanes, values);
#endif
  return (void)m, (void)lanes, (void)values, false;  // not built for this width
}

}  // namespace tribex::materials::every_model
