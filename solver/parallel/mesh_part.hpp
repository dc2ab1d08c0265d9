// SPDX-License-Identifier: MIT
// The distributed set-up of a parallel run (solver/README.md "Parallel runs"): rank 0 reads or
// generates the whole mesh and partitions it; every rank receives only its part, a mesh in local
// numbering with the global numbers of its nodes and elements and the ranks that hold each node,
// and builds its model from that alone (build_model on a MeshPart). No rank but 0 ever holds the
// whole mesh, and rank 0 only during set-up.
//
// Local numbering: the rank's elements and the nodes of those elements, each ascending in global
// number (so local order = global order, and restricted sets keep their order). Every block, node
// set and side set of the whole mesh is present by name, possibly empty, with its whole-mesh size.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::solver::parallel {

/// The ranks holding each node of the whole mesh (the parts of its elements), CSR, ascending.
struct NodeHolders {
  std::vector<int> offset;  // [global node + 1]
  std::vector<int> rank;
  int count(int node) const { return offset[node + 1] - offset[node]; }
};

struct MeshPart {
  mesh::Mesh mesh;
  std::vector<int> global_node;     // [local node]
  std::vector<int> global_element;  // [local element]
  std::vector<int> holder_offset;   // [local node + 1] into holder_rank
  std::vector<int> holder_rank;     // the ranks holding each local node, ascending (this rank among them)
  int global_node_count = 0, global_element_count = 0;
  std::map<std::string, int> node_set_size, side_set_size;  // of the whole mesh
};

/// Throws SetupError naming the first node of `mesh` in no element (it would have no mass).
NodeHolders node_holders(const mesh::Mesh& mesh, const std::vector<int>& part);

/// Rank `rank`'s part of `whole` under the element partition `part` (pure; rank 0 calls it for every rank).
MeshPart split_mesh(const mesh::Mesh& whole, const std::vector<int>& part, const NodeHolders& holders, int rank);

/// Collective. Rank 0 passes the whole mesh, its partition and node_holders of them, and sends every
/// other rank its part (one message each, in pieces under 1 GiB); the other ranks pass nullptr and
/// receive theirs. Nothing in it throws on one rank only (node_holders, which checks the mesh, comes first).
MeshPart distribute_mesh(const mesh::Mesh* whole, const std::vector<int>* part, const NodeHolders* holders);

/// A part as bytes (the message distribute_mesh sends), and back.
std::vector<char> pack_part(const MeshPart& part);
MeshPart unpack_part(const std::vector<char>& bytes);

}  // namespace tribex::solver::parallel
