// SPDX-License-Identifier: MIT
#include "solver/setup/surface_layer_blocks.hpp"

#include "inputs/did_you_mean.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/surface_layers.hpp"
#include "solver/errors.hpp"

namespace tribex::solver {
namespace {

[[noreturn]] void fail(const inputs::SourceLocation& where, const std::string& what) {
  throw SetupError(where.str() + ": error: surface layer block: " + what);
}

std::string hint(const std::string& name, const std::vector<std::string>& known) {
  const std::string h = inputs::closest_match(name, known);
  return h.empty() ? "" : " (did you mean '" + h + "'?)";
}

}  // namespace

void apply_surface_layer_blocks(mesh::Mesh& mesh, const inputs::FiniteElementModelSpec& spec) {
  for (const auto& sl : spec.surface_layers) {
    std::vector<std::string> blocks, surfaces;
    for (const auto& b : mesh.blocks) blocks.push_back(b.name);
    for (const auto& [name, sides] : mesh.side_sets) surfaces.push_back(name);
    for (const auto& [name, nodes] : mesh.node_sets) surfaces.push_back(name);
    const mesh::Block* parent = mesh.find_block(sl.from_block);
    if (!parent) fail(sl.from_block_where, "block '" + sl.from_block + "' is not in the mesh" + hint(sl.from_block, blocks));
    if (mesh.find_block(sl.name))
      fail(sl.where, "'" + sl.name + "' already names a block of the mesh; choose another name");
    if (!mesh.side_sets.count(sl.surface) && !mesh.node_sets.count(sl.surface))
      fail(sl.surface_where,
           "surface '" + sl.surface + "' is neither a side set nor a node set of the mesh" + hint(sl.surface, surfaces));
    const int parent_count = parent->element_count;
    const mesh::SurfaceLayerSplit split{sl.from_block, sl.surface, sl.layers, sl.name};
    try {
      // Checked before the split so that a refused split leaves the mesh as it was.
      const auto skin = mesh::surface_layer_elements(mesh, split);
      int taken = 0;
      for (char c : skin) taken += c;
      if (taken == parent_count)
        fail(sl.where, "layers = " + std::to_string(sl.layers) + " takes all " + std::to_string(parent_count) +
                           " elements of block '" + sl.from_block + "'; give that block the section instead, or fewer layers");
      mesh::split_surface_layers(mesh, split);
    } catch (const mesh::MeshError& e) {
      fail(sl.where, e.what());
    }
  }
}

}  // namespace tribex::solver
