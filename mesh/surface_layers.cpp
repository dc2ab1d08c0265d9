// SPDX-License-Identifier: MIT
#include "mesh/surface_layers.hpp"

#include <algorithm>
#include <numeric>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

const Block& parent_of(const Mesh& mesh, const SurfaceLayerSplit& split) {
  const Block* b = mesh.find_block(split.block);
  if (!b) throw MeshError("surface layer block '" + split.name + "': block '" + split.block + "' is not in the mesh");
  return *b;
}

// Nodes of the surface that lie on the block: a side set's faces on the block, else a node set.
std::vector<char> surface_nodes(const Mesh& mesh, const Block& b, const SurfaceLayerSplit& split) {
  std::vector<char> on(static_cast<std::size_t>(mesh.node_count()), 0);
  const int first = b.first_element, end = b.first_element + b.element_count;
  if (auto s = mesh.side_sets.find(split.surface); s != mesh.side_sets.end()) {
    for (const Side& side : s->second)
      if (side.element >= first && side.element < end)
        for (int n : mesh.side_nodes(side)) on[n] = 1;
  } else if (auto ns = mesh.node_sets.find(split.surface); ns != mesh.node_sets.end()) {
    for (int n : ns->second) on[n] = 1;
  } else {
    throw MeshError("surface layer block '" + split.name + "': the mesh has no side set or node set '" +
                    split.surface + "'");
  }
  return on;
}

}  // namespace

std::vector<char> surface_layer_elements(const Mesh& mesh, const SurfaceLayerSplit& split) {
  const Block& b = parent_of(mesh, split);
  if (split.layers < 1)
    throw MeshError("surface layer block '" + split.name + "': layers = " + std::to_string(split.layers) +
                    "; give 1 or more");
  std::vector<char> front = surface_nodes(mesh, b, split);  // nodes of the previous layer (or the surface)
  std::vector<char> taken(static_cast<std::size_t>(mesh.element_count()), 0);
  const int first = b.first_element, end = b.first_element + b.element_count;
  bool touches = false;
  for (int layer = 1; layer <= split.layers; ++layer) {
    std::vector<int> added;
    for (int e = first; e < end; ++e) {
      if (taken[e]) continue;
      for (int a = 0; a < 8; ++a)
        if (front[mesh.connectivity[8 * static_cast<std::size_t>(e) + a]]) {
          added.push_back(e);
          break;
        }
    }
    if (layer == 1) touches = !added.empty();
    if (added.empty()) break;  // the block is used up
    // The next layer is whatever shares a node with this one.
    std::fill(front.begin(), front.end(), 0);
    for (int e : added) {
      taken[e] = 1;
      for (int a = 0; a < 8; ++a) front[mesh.connectivity[8 * static_cast<std::size_t>(e) + a]] = 1;
    }
  }
  if (!touches)
    throw MeshError("surface layer block '" + split.name + "': surface '" + split.surface + "' has no node on block '" +
                    split.block + "'");
  return taken;
}

SurfaceLayerCounts split_surface_layers(Mesh& mesh, const SurfaceLayerSplit& split) {
  if (mesh.find_block(split.name))
    throw MeshError("surface layer block '" + split.name + "': the mesh already has a block of that name");
  const std::vector<char> skin = surface_layer_elements(mesh, split);
  const auto parent = std::find_if(mesh.blocks.begin(), mesh.blocks.end(),
                                   [&](const Block& b) { return b.name == split.block; });
  const int first = parent->first_element, count = parent->element_count;

  // old_of[new] for the parent's range: the rest first, then the skin, each in its old order.
  std::vector<int> old_of;
  old_of.reserve(static_cast<std::size_t>(count));
  for (int pass = 0; pass < 2; ++pass)
    for (int e = first; e < first + count; ++e)
      if (static_cast<bool>(skin[e]) == (pass == 1)) old_of.push_back(e);
  SurfaceLayerCounts counts;
  counts.skin = static_cast<int>(std::count(skin.begin() + first, skin.begin() + first + count, 1));
  counts.rest = count - counts.skin;

  std::vector<int> new_of(static_cast<std::size_t>(mesh.element_count()));
  std::iota(new_of.begin(), new_of.end(), 0);
  std::vector<int> moved(8 * static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    new_of[old_of[k]] = first + k;
    std::copy_n(mesh.connectivity.begin() + 8 * static_cast<std::ptrdiff_t>(old_of[k]), 8, moved.begin() + 8 * k);
  }
  std::copy(moved.begin(), moved.end(), mesh.connectivity.begin() + 8 * static_cast<std::ptrdiff_t>(first));
  for (auto& [name, sides] : mesh.side_sets) {
    const bool sorted = std::is_sorted(sides.begin(), sides.end());
    for (Side& s : sides) s.element = new_of[s.element];
    if (sorted) std::sort(sides.begin(), sides.end());
  }

  // The new block right after its parent, so that blocks stay in element order.
  const Block skin_block{split.name, first + counts.rest, counts.skin};
  parent->element_count = counts.rest;
  auto at = mesh.blocks.insert(parent + 1, skin_block);
  if (counts.skin == 0) mesh.blocks.erase(at);
  else if (counts.rest == 0) mesh.blocks.erase(at - 1);
  return counts;
}

}  // namespace tribex::mesh
