// SPDX-License-Identifier: MIT
// The wider lane widths of every_model_test.cpp, each compiled in its own file with the instruction
// set it needs (tests/materials/CMakeLists.txt): the points of every_model_support.hpp at four lanes
// (every_model_avx2.cpp, double4) and eight (every_model_avx512.cpp, double8). false: the file was not
// built for that width (another compiler or CPU family). `values`: values_per_run<M>(lanes) doubles.
#pragma once

#include "materials/material.hpp"

namespace tribex::materials::every_model {

bool run_four_lanes(const Material& m, int lanes, double* values);
bool run_eight_lanes(const Material& m, int lanes, double* values);

}  // namespace tribex::materials::every_model
