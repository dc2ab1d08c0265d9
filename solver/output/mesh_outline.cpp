// SPDX-License-Identifier: MIT
#include "solver/output/mesh_outline.hpp"

#include "solver/parallel/communicator.hpp"

namespace tribex::solver::output {

MeshOutline outline_of(const mesh::Mesh& mesh, const std::string& length_unit_choice, bool parallel) {
  MeshOutline o;
  const bool mine = !parallel || parallel::is_root();
  if (mine) {
    o.nodes = mesh.node_count();
    o.elements = mesh.element_count();
    o.blocks = mesh.blocks;
    o.unit = resolve_length_unit(length_unit_choice, mesh);
  }
  if (!parallel) return o;
  // Counts and block ranges as ints (a mesh's indices are ints), names and the unit as text.
  std::vector<int> numbers{static_cast<int>(o.nodes), static_cast<int>(o.elements), static_cast<int>(o.blocks.size())};
  parallel::broadcast(numbers.data(), 3, 0);
  o.nodes = numbers[0];
  o.elements = numbers[1];
  o.blocks.resize(static_cast<std::size_t>(numbers[2]));
  std::vector<int> ranges(2 * o.blocks.size());
  for (std::size_t b = 0; b < o.blocks.size(); ++b) {
    ranges[2 * b] = o.blocks[b].first_element;
    ranges[2 * b + 1] = o.blocks[b].element_count;
  }
  parallel::broadcast(ranges.data(), static_cast<int>(ranges.size()), 0);
  for (std::size_t b = 0; b < o.blocks.size(); ++b) {
    o.blocks[b].first_element = ranges[2 * b];
    o.blocks[b].element_count = ranges[2 * b + 1];
    parallel::broadcast(o.blocks[b].name, 0);
  }
  std::string unit = o.unit.name;
  parallel::broadcast(unit, 0);
  if (!mine) o.unit = length_unit_named(unit);
  return o;
}

}  // namespace tribex::solver::output
