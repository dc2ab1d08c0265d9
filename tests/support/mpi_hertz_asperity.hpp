// SPDX-License-Identifier: MIT
// The generated asperity of tests/parallel/mpi_hertz.i (1.6 nm elements, 3,964 hex8): the small mesh the
// per-rank generation and partition tests build in code; and that asperity beside a graded box (two blocks of
// hexes, side sets on both bodies), the mesh the slab tests of the file readers write and read back.
#pragma once

#include <array>

#include "mesh/asperity.hpp"
#include "mesh/box.hpp"
#include "mesh/mesh.hpp"
#include "tests/support/asperity_outline.hpp"

namespace tribex::test {

inline mesh::AsperitySpec mpi_hertz_asperity() {
  mesh::AsperitySpec a = asperity_outline(27e-9, 32e-9, 26e-9, 60e-9, 30e-9, 1.6e-9);
  a.fine_half_width = 6.4e-9;
  a.fine_depth = 3.2e-9;
  a.grading_ratio = 1.35;
  return a;
}

// The box (20 x 15 x 12 nm, graded toward its top) has `intervals` cells and lies beside the asperity.
inline mesh::Mesh box_beside_mpi_hertz_asperity(const std::array<int, 3>& intervals) {
  mesh::BoxSpec block;
  block.name = "block";
  block.origin = {-60e-9, -40e-9, -30e-9};
  block.size = {20e-9, 15e-9, 12e-9};
  block.intervals = intervals;
  block.grade_toward = "zmax";
  block.grading_ratio = 1.3;
  mesh::Mesh m;
  mesh::add_box(m, block);
  mesh::append(m, mesh::generate_asperity(mpi_hertz_asperity()));
  return m;
}

}  // namespace tribex::test
