// SPDX-License-Identifier: MIT
// A generated mesh (boxes, the asperity) described without its volume, so that a rank builds any
// range of its elements alone (issue 57 scope 2: set-up with no rank holding the whole mesh).
//
// The generators (box.hpp, asperity.hpp) make their meshes of structured grids: grid g numbers its
// node (i, j, k) node_offset + i + (nx+1)(j + (ny+1)k) and its element (i, j, k) element_offset +
// i + nx(j + ny k), and a node's coordinates are the grid's axes at (i, j, k), then mapped (the
// asperity tip's bottom follows the sphere; `apex position` translates). So the element numbers, the
// node numbers and the coordinates follow from (grid, i, j, k) directly, with the same arithmetic as
// the serial generator (bitwise the same coordinates): no pass over the mesh is needed, only the
// grids' axes (O(N^(1/3)) each). What a plan holds whole are the sets of the surfaces (O(N^(2/3)):
// the same order as the contact faces every rank already holds) and the blocks; a grid's node set
// NAME_all (O(N)) is held as its node range.
//
// generate_elements(plan, elements) is the mesh of those elements (any sorted list of global element
// numbers: a contiguous slab, or a rank's part) in local numbering, each ascending in global number,
// sets restricted (node sets to its nodes, side sets to its elements, in the whole set's order): the
// layout of a parallel MeshPart (solver/parallel/mesh_part.hpp). tests/parallel_unit/mpi/
// generated_slab_test.cpp checks that the slabs of every rank count are the serial mesh.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::mesh {

struct GridPiece {
  std::array<std::vector<double>, 3> axes;  // node coordinates along x, y, z before the map, m
  int node_offset = 0, element_offset = 0;  // the grid's first node and element in the whole mesh
  /// Applied to each node's (x, y, z) after the axes (the tip's sphere, the apex translation); empty: none.
  std::function<void(double* xyz)> map;
  int nodes() const;
  int elements() const;
};

struct GeneratedPlan {
  std::vector<GridPiece> grids;  // ascending offsets, together every node and element once
  std::vector<Block> blocks;
  std::map<std::string, std::vector<int>> node_sets;           // whole-mesh numbers, sorted (not the ranges)
  std::map<std::string, std::array<int, 2>> node_set_ranges;   // NAME_all: every node in [first, end)
  std::map<std::string, std::vector<Side>> side_sets;          // whole-mesh numbers, the generator's order
  int node_count = 0, element_count = 0;
  /// Whole-mesh size of each node set (ranges included) and side set.
  std::map<std::string, int> node_set_sizes() const;
  std::map<std::string, int> side_set_sizes() const;
};

/// The mesh of `elements` (global numbers, ascending, unique) in local numbering; `global_node` gets
/// its nodes' global numbers, ascending. Every block and set of the plan is present by name (possibly empty).
Mesh generate_elements(const GeneratedPlan& plan, const std::vector<int>& elements, std::vector<int>& global_node);

/// The global node numbers of `elements`' 8 corners, [element][8] (the input of the face dual graph).
std::vector<int> element_nodes(const GeneratedPlan& plan, int first, int count);

/// The grid (index into plan.grids) holding global node `node`.
int grid_of_node(const GeneratedPlan& plan, int node);

/// The coordinates of the nodes [first, first + count), [node][3] (a streamed pass over the mesh).
std::vector<double> node_coordinates(const GeneratedPlan& plan, int first, int count);

/// Appends `other` to `into` with its node and element numbers shifted past those of `into`, as
/// append(Mesh&, const Mesh&) does (a name in both: MeshError).
void append_plan(GeneratedPlan& into, GeneratedPlan other);

}  // namespace tribex::mesh
