// SPDX-License-Identifier: MIT
#include "solver/parallel/partition.hpp"

#include <metis.h>

#include <stdexcept>
#include <string>

namespace tribex::solver::parallel {

std::vector<int> partition_elements(const mesh::Mesh& mesh, int parts, const std::vector<std::vector<char>>& balanced) {
  const int ne = mesh.element_count();
  std::vector<int> part(static_cast<std::size_t>(ne), 0);
  if (parts <= 1 || ne == 0) return part;
  if (parts > ne) throw std::runtime_error("more ranks (" + std::to_string(parts) + ") than elements (" + std::to_string(ne) + ")");
  idx_t n_elements = ne, n_nodes = mesh.node_count(), n_common = 4, numbering = 0;
  // The dual graph from the connectivity as it is where idx_t is int (METIS reads it, does not write
  // it), else from a copy; the element offsets are freed before the partitioning, whose workspace is
  // rank 0's peak memory in a parallel set-up (tools/bench/README.md "Counts per rank").
  std::vector<idx_t> eptr(static_cast<std::size_t>(ne) + 1), copy;
  for (int e = 0; e <= ne; ++e) eptr[e] = 8 * e;
  idx_t* eind = nullptr;
  if constexpr (sizeof(idx_t) == sizeof(int)) {
    eind = reinterpret_cast<idx_t*>(const_cast<int*>(mesh.connectivity.data()));
  } else {
    copy.assign(mesh.connectivity.begin(), mesh.connectivity.end());
    eind = copy.data();
  }
  idx_t *xadj = nullptr, *adjncy = nullptr;
  if (METIS_MeshToDual(&n_elements, &n_nodes, eptr.data(), eind, &n_common, &numbering, &xadj, &adjncy) != METIS_OK)
    throw std::runtime_error("METIS_MeshToDual failed");
  eptr = {};
  copy = {};
  // Vertex weights: 1 per element for the work, and per balanced set 1 on its elements (multi-constraint
  // k-way: every part gets about 1/parts of each).
  std::vector<const std::vector<char>*> sets;
  for (const auto& set : balanced) {
    long marked = 0;
    for (char c : set) marked += c != 0;
    if (set.size() == static_cast<std::size_t>(ne) && marked >= parts) sets.push_back(&set);
  }
  idx_t n_constraints = 1 + static_cast<idx_t>(sets.size()), n_parts = parts, cut = 0;
  std::vector<idx_t> weights;
  if (!sets.empty()) {
    weights.assign(static_cast<std::size_t>(ne) * n_constraints, 0);
    for (int e = 0; e < ne; ++e) {
      weights[static_cast<std::size_t>(e) * n_constraints] = 1;
      for (std::size_t c = 0; c < sets.size(); ++c)
        weights[static_cast<std::size_t>(e) * n_constraints + 1 + c] = (*sets[c])[e] != 0;
    }
  }
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;         // the same partition on every rank and every run
  std::vector<idx_t> result(static_cast<std::size_t>(ne));
  const int status = METIS_PartGraphKway(&n_elements, &n_constraints, xadj, adjncy, weights.empty() ? nullptr : weights.data(),
                                         nullptr, nullptr, &n_parts, nullptr, nullptr, options, &cut, result.data());
  METIS_Free(xadj);
  METIS_Free(adjncy);
  if (status != METIS_OK) throw std::runtime_error("METIS_PartGraphKway failed (status " + std::to_string(status) + ")");
  for (int e = 0; e < ne; ++e) part[e] = static_cast<int>(result[e]);
  return part;
}

}  // namespace tribex::solver::parallel
