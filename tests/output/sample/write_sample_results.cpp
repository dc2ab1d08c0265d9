// SPDX-License-Identifier: MIT
// Writes the sample results pair (tests/output/sample_case.hpp) into the directory given as the
// first argument: the CTest fixture that check_xdmf_paraview.py reads. A second argument "nm"
// writes the same case as a 3 nm x 2 nm x 2 nm model (the file then in nanometres).
#include <cstdio>
#include <exception>
#include <string>

#include "../sample_case.hpp"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3 || (argc == 3 && std::string(argv[2]) != "nm")) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIRECTORY [nm]\n", argv[0]);
    return 2;
  }
  try {
    tribex::test::write_sample_case(argv[1], argc == 3 ? 1e-9 : 1.0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
