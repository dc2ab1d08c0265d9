// SPDX-License-Identifier: MIT
// One rank's results file of a parallel run, DIR/results.exo.N.r (README.md "Exodus II output",
// "Parallel: one file per rank"): the Nemesis "spread" layout that SEACAS's epu joins and ParaView's
// Exodus readers open as one data set. Each rank writes its elements and the nodes they use, with
// the whole mesh's numbers in the node and element number maps, every block and set of the whole
// mesh (empty where the rank has none of it), and the Nemesis global counts.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "solver/output/mesh_outline.hpp"
#include "solver/parallel/domain.hpp"

namespace tribex::solver::output {

/// "results.exo.N.r", r zero-padded to the digits of N (epu's and nem_spread's names: results.exo.16.03).
std::string rank_file_name(int ranks, int rank);

/// The mesh of a rank's file: `local` (the rank's elements and the nodes they use) with the whole mesh's
/// blocks from `outline` in its element order (a block the rank has no element of kept empty, so that
/// block ids are the same on every rank) and every node and side set any rank has (collective: the set
/// names are gathered, as a rank may hold none of a set's members).
mesh::Mesh rank_file_mesh(const mesh::Mesh& local, const MeshOutline& outline);

/// The whole mesh's element count of each block and member count of each set of `file_mesh` (collective).
struct RankGlobals {
  std::vector<int> block_counts, node_set_sizes, side_set_sizes;
};
RankGlobals rank_globals(const mesh::Mesh& file_mesh, const parallel::Domain& domain);

/// Writes into the open file `exo` what joins it to the others: the node and element number maps
/// (global index + 1) and the Nemesis records (init_info, init_global, the global block and set
/// counts, internal/border nodes and the node communication maps of the shared nodes). Not
/// collective. Returns a negative status on a write failure.
int put_rank_maps(int exo, const mesh::Mesh& file_mesh, const parallel::Domain& domain, const MeshOutline& outline,
                  const RankGlobals& globals);

/// A rank's rows of a nodal field for its file: the owned nodes' rows come with the field (the rows
/// results.h5 takes), the others' (shared nodes owned by a lower rank) from their owners, one
/// sparse_alltoallv per field (parallel/sparse_exchange.hpp; the pattern built once, at construction: collective).
class SharedNodeRows {
 public:
  explicit SharedNodeRows(const parallel::Domain& domain);
  /// `owned_rows` [owned node][components] -> `local` [local node][components]. Collective.
  void fill(const double* owned_rows, int components, std::vector<double>& local);

 private:
  int local_nodes_ = 0;
  std::vector<int> owned_local_;               // [owned row] local node
  std::vector<int> send_row_;                  // owned rows to send, grouped by rank
  std::vector<int> send_counts_, send_displs_;  // nodes
  std::vector<int> receive_local_;             // local nodes received, grouped by rank
  std::vector<int> receive_counts_, receive_displs_;
  std::vector<double> send_, receive_;
  std::vector<int> counts_, displs_, rcounts_, rdispls_;  // doubles, per call
};

}  // namespace tribex::solver::output
