// SPDX-License-Identifier: MIT
// The generated asperity of tests/parallel/mpi_hertz.i (1.6 nm elements, 3,964 hex8): the small mesh the
// per-rank generation and partition tests build in code.
#pragma once

#include "mesh/asperity.hpp"

namespace tribex::test {

inline mesh::AsperitySpec mpi_hertz_asperity() {
  mesh::AsperitySpec a;
  a.radius = 27e-9;
  a.tip_width = 32e-9;
  a.tip_height = 26e-9;
  a.substrate_width = 60e-9;
  a.substrate_depth = 30e-9;
  a.element_size = 1.6e-9;
  a.fine_half_width = 6.4e-9;
  a.fine_depth = 3.2e-9;
  a.grading_ratio = 1.35;
  return a;
}

}  // namespace tribex::test
