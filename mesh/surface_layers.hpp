// SPDX-License-Identifier: MIT
// Split the element layers under a surface off a block into a block of their own ("mixed blocks":
// a fully integrated skin under contact, one-point elements below; deck `begin surface layer block`).
//
// Layers are topological: layer 1 = the block's elements with a node on the surface, layer k = the
// block's elements not yet taken that share a node with layer k - 1. Elements are renumbered so
// that every block stays one contiguous range; nodes keep their numbers.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::mesh {

struct SurfaceLayerSplit {
  std::string block;    // the block to split (must exist)
  std::string surface;  // a side set (its faces on `block`) or, without one, a node set of that name
  int layers = 1;       // >= 1
  std::string name;     // the new block's name (must not name a block yet)
};

struct SurfaceLayerCounts {
  int skin = 0;  // elements moved into the new block
  int rest = 0;  // elements left in the parent block
};

/// Which elements of `split.block` lie within `split.layers` layers of the surface: a flag per
/// element of the mesh. MeshError for an unknown block or surface, layers < 1, or a surface with no
/// node on the block.
std::vector<char> surface_layer_elements(const Mesh& mesh, const SurfaceLayerSplit& split);

/// Split the block in place. The parent's range [f, f + n) becomes [f, f + rest) with its
/// remaining elements and, right after it, the new block [f + rest, f + n) with the skin, both in
/// their previous relative order; every other element keeps its number (so only element numbers
/// inside the split block change). Side sets are renumbered (and stay sorted when they were);
/// node sets and coordinates are untouched. When the skin takes every element of the parent, the
/// parent (now empty) is removed and the new block holds them all; the skin is never empty (a
/// surface with no node on the block is a MeshError). MeshError as above, or when `split.name`
/// already names a block.
SurfaceLayerCounts split_surface_layers(Mesh& mesh, const SurfaceLayerSplit& split);

}  // namespace tribex::mesh
