// SPDX-License-Identifier: MIT
// The deck's `begin surface layer block` -> mesh/surface_layers.hpp, applied to the mesh of any
// source (generated, AFM, gmsh, Exodus) once it is built or read.
#pragma once

#include "inputs/deck.hpp"
#include "mesh/mesh.hpp"

namespace tribex::solver {

/// Splits the blocks in deck order (a later one may split a block an earlier one made). An unknown
/// block or surface, a name the mesh already has, a surface off the block, or layers that take the
/// whole block are a SetupError "DECK:LINE: error: ..." (exit code 2).
void apply_surface_layer_blocks(mesh::Mesh& mesh, const inputs::FiniteElementModelSpec& spec);

}  // namespace tribex::solver
