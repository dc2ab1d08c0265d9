// SPDX-License-Identifier: MIT
// Writes the sample results pair (tests/output/sample_case.hpp) into the directory given as the
// only argument: the CTest fixture that check_xdmf_paraview.py reads.
#include <cstdio>
#include <exception>

#include "../sample_case.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIRECTORY\n", argv[0]);
    return 2;
  }
  try {
    tribex::test::write_sample_case(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
