// SPDX-License-Identifier: MIT
// Every model at four lanes (double4, lanes.hpp), built with -mavx2 -mno-fma like
// solver/hex8/avx2_kernels.cpp (tests/materials/CMakeLists.txt); only the double4 code is made here.
#include "tests/materials/every_model_lanes.hpp"
#include "tests/materials/every_model_support.hpp"

namespace tribex::materials::every_model {

bool run_four_lanes(const Material& m, int lanes, double* values) {
#ifdef __AVX2__
  std::visit([&](const auto& model) { run_at_width<double4>(model, lanes, values); }, m);
  return true;
#else
  (void)m, (void)lanes, (void)values;
  return false;
#endif
}

}  // namespace tribex::materials::every_model
