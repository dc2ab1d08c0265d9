// SPDX-License-Identifier: MIT
// The deck's `begin afm surface` -> the mesh generator of mesh/afm/afm_mesh.hpp.
#pragma once

#include "inputs/deck.hpp"
#include "mesh/mesh.hpp"

namespace tribex::solver {

/// Reads the map, levels it and builds the substrate block; a bad map or spec becomes a SetupError
/// "DECK:LINE:COL: error: 'begin afm surface': ..." (exit code 2).
mesh::Mesh build_afm_surface_mesh(const inputs::AfmSurfaceSpec& spec);

}  // namespace tribex::solver
