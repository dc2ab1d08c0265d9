// SPDX-License-Identifier: MIT
// The mesh the partition tests start from: a unit cube of n x n x n elements (mesh/box.hpp numbering).
#pragma once

#include "mesh/box.hpp"

namespace tribex::test {

inline mesh::Mesh cube_mesh(int n) {
  mesh::BoxSpec spec;
  spec.intervals = {n, n, n};
  return mesh::generate_box(spec);
}

}  // namespace tribex::test
