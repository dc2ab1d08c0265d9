// SPDX-License-Identifier: MIT
// Where the distributed set-up (`set-up = distributed`, source_parts.hpp) takes a mesh from when no rank
// holds it whole: an element source answers, on every rank, the few questions the pipeline asks (the
// counts; this rank's slab of the even split of the elements; the mesh of any sorted list of elements;
// the elements of named side sets). Two sources: a generated mesh's plan (PlanSource: every rank computes
// any element from the grids alone, mesh/generated_plan.hpp) and an Exodus II or gmsh MSH 4.1 file read
// in slices (FileSliceSource, file_slice_source.hpp: each rank reads a slab of the elements and an even share of
// the nodes and sets, and serves the other ranks' requests). The pipeline calls every member on every rank
// at the same point, so that a source may answer collectively (the Exodus one does; the plan's does not
// need to).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mesh/generated_plan.hpp"
#include "mesh/mesh.hpp"

namespace tribex::solver::parallel {

class ElementSource {
 public:
  virtual ~ElementSource() = default;
  virtual int element_count() const = 0;
  virtual int node_count() const = 0;
  /// The blocks of the whole mesh (element ranges in the whole mesh's numbering).
  virtual const std::vector<mesh::Block>& blocks() const = 0;
  /// Whole-mesh sizes of every node set and side set, by name.
  virtual std::map<std::string, int> node_set_sizes() const = 0;
  virtual std::map<std::string, int> side_set_sizes() const = 0;
  /// The 8 global nodes of this rank's slab of the even split (slab_offsets), [element][8].
  virtual std::vector<int> slab_nodes() const = 0;
  /// Collective: the mesh of `elements` (global numbers, ascending, unique; each rank its own list) in local
  /// numbering, `global_node` its nodes ascending; every block and set of the whole mesh present by name,
  /// restricted to them (node sets to its nodes ascending, side sets to its elements in the set's order):
  /// split_mesh's layout (mesh_part.hpp).
  virtual mesh::Mesh elements_mesh(const std::vector<int>& elements, std::vector<int>& global_node) const = 0;
  /// Collective: the elements of the named side sets (names the mesh lacks skipped), ascending, unique,
  /// the same on every rank.
  virtual std::vector<int> side_set_elements(const std::vector<std::string>& names) const = 0;
};

/// A generated mesh's plan as a source: nothing collective.
class PlanSource final : public ElementSource {
 public:
  explicit PlanSource(mesh::GeneratedPlan plan) : plan_(std::move(plan)) {}
  int element_count() const override { return plan_.element_count; }
  int node_count() const override { return plan_.node_count; }
  const std::vector<mesh::Block>& blocks() const override { return plan_.blocks; }
  std::map<std::string, int> node_set_sizes() const override { return plan_.node_set_sizes(); }
  std::map<std::string, int> side_set_sizes() const override { return plan_.side_set_sizes(); }
  std::vector<int> slab_nodes() const override;
  mesh::Mesh elements_mesh(const std::vector<int>& elements, std::vector<int>& global_node) const override {
    return mesh::generate_elements(plan_, elements, global_node);
  }
  std::vector<int> side_set_elements(const std::vector<std::string>& names) const override;
  const mesh::GeneratedPlan& plan() const { return plan_; }

 private:
  mesh::GeneratedPlan plan_;
};

}  // namespace tribex::solver::parallel
