// SPDX-License-Identifier: MIT
#include "solver/parallel/element_slabs.hpp"

#include <mpi.h>

#include <stdexcept>

#include "solver/parallel/communicator.hpp"
#include "solver/parallel/face_dual_graph.hpp"
#include "solver/parallel/ptscotch_partition.hpp"

namespace tribex::solver::parallel {

std::vector<int> slab_offsets(int elements, int ranks) {
  std::vector<int> offset(static_cast<std::size_t>(ranks + 1), 0);
  for (int r = 0; r < ranks; ++r) offset[r + 1] = offset[r] + elements / ranks + (r < elements % ranks ? 1 : 0);
  return offset;
}

ElementSlab scatter_element_slabs(const mesh::Mesh* whole) {
  const int ranks = size(), me = rank();
  int elements = whole ? whole->element_count() : 0;
  broadcast(&elements, 1, 0);
  // MPI_Scatterv's int displacements, 8 per element: up to 268 M elements (every rank throws alike).
  if (8.0 * elements > 2147483647.0) throw std::runtime_error("more than 268 M elements to scatter in slabs");
  const std::vector<int> offset = slab_offsets(elements, ranks);
  ElementSlab slab;
  slab.first = offset[me];
  slab.count = offset[me + 1] - offset[me];
  if (ranks == 1) {
    slab.nodes = whole->connectivity;
    return slab;
  }
  std::vector<int> count(static_cast<std::size_t>(ranks)), at(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) {
    count[r] = 8 * (offset[r + 1] - offset[r]);
    at[r] = 8 * offset[r];
  }
  slab.nodes.resize(8 * static_cast<std::size_t>(slab.count));
  MPI_Scatterv(whole ? whole->connectivity.data() : nullptr, count.data(), at.data(), MPI_INT, slab.nodes.data(),
               count[me], MPI_INT, 0, MPI_COMM_WORLD);
  return slab;
}

std::vector<int> gather_slab_parts(const ElementSlab& slab, const std::vector<int>& part) {
  const int ranks = size(), me = rank();
  if (ranks == 1) return part;
  std::vector<int> count(static_cast<std::size_t>(ranks)), at(static_cast<std::size_t>(ranks));
  const int mine[2] = {slab.first, slab.count};
  std::vector<int> slabs(static_cast<std::size_t>(2 * ranks));
  MPI_Gather(mine, 2, MPI_INT, slabs.data(), 2, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> whole;
  if (me == 0) {
    for (int r = 0; r < ranks; ++r) {
      at[r] = slabs[2 * r];
      count[r] = slabs[2 * r + 1];
    }
    whole.resize(static_cast<std::size_t>(at[ranks - 1]) + count[ranks - 1]);
  }
  MPI_Gatherv(part.data(), slab.count, MPI_INT, whole.data(), count.data(), at.data(), MPI_INT, 0, MPI_COMM_WORLD);
  return whole;
}

std::vector<int> partition_elements_ptscotch(const mesh::Mesh* whole, int parts) {
  const ElementSlab slab = scatter_element_slabs(whole);
  const DualGraphRows rows = face_dual_graph(slab);
  return gather_slab_parts(slab, ptscotch_parts(rows, parts));
}

}  // namespace tribex::solver::parallel
