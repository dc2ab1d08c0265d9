// SPDX-License-Identifier: MIT
// What the writers of results.h5 and results.exo need to know of the whole mesh on every rank: its
// counts, blocks and length unit. In a parallel run only rank 0 holds the whole mesh (solver/README.md
// "Parallel runs"), so the outline is rank 0's, broadcast; rank 0 alone writes the mesh's arrays.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "solver/output/length_unit.hpp"

namespace tribex::solver::output {

struct MeshOutline {
  long long nodes = 0, elements = 0;
  std::vector<mesh::Block> blocks;
  LengthUnit unit;
};

/// The outline of `mesh` with the length unit resolved from `length_unit_choice` ("auto": from its
/// extent). `parallel`: collective, every rank gets rank 0's (whose `mesh` is the whole mesh).
MeshOutline outline_of(const mesh::Mesh& mesh, const std::string& length_unit_choice, bool parallel);

}  // namespace tribex::solver::output
