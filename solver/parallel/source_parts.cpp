// SPDX-License-Identifier: MIT
#include "solver/parallel/source_parts.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "solver/parallel/sparse_exchange.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/contact_partition.hpp"
#include "solver/parallel/element_slab.hpp"
#include "solver/parallel/face_dual_graph.hpp"
#include "solver/parallel/ptscotch_partition.hpp"

namespace tribex::solver::parallel {
namespace {

// Step 3: this rank's elements (global numbers, ascending) under the partition of the slabs.
std::vector<int> partitioned_elements(int element_count, std::vector<int> part) {
  const int ranks = size(), me = rank();
  const int first = slab_offsets(element_count, ranks)[me];
  std::vector<int> count(static_cast<std::size_t>(ranks), 0);
  for (int p : part) ++count[p];
  std::vector<int> at(static_cast<std::size_t>(ranks) + 1, 0);
  for (int r = 0; r < ranks; ++r) at[r + 1] = at[r] + count[r];
  std::vector<int> data(part.size());
  for (std::size_t e = 0; e < part.size(); ++e) data[static_cast<std::size_t>(at[part[e]]++)] = first + static_cast<int>(e);
  part = {};
  std::vector<int> received;
  std::vector<int> mine = exchange(count, data, received);
  std::sort(mine.begin(), mine.end());
  return mine;
}

// Step 5: the ranks holding each of this rank's nodes (ascending global numbers), CSR into the part.
long long fill_holders(const std::vector<int>& global_node, int node_count, MeshPart& p) {
  const int ranks = size(), me = rank();
  const std::vector<int> home_offset = slab_offsets(node_count, ranks);
  std::vector<int> count(static_cast<std::size_t>(ranks), 0);
  for (int n : global_node) ++count[static_cast<std::size_t>(home_of(home_offset, n))];
  std::vector<int> from;
  const std::vector<int> asked = exchange(count, global_node, from);  // ascending within each source
  // The home's nodes [lo, hi): each one's holders in source-rank order, i.e. ascending.
  const int lo = home_offset[me], hi = home_offset[me + 1];
  std::vector<int> offset(static_cast<std::size_t>(hi - lo) + 1, 0);
  for (int n : asked) ++offset[static_cast<std::size_t>(n - lo) + 1];
  for (int n = 0; n < hi - lo; ++n) offset[n + 1] += offset[n];
  std::vector<int> holder(static_cast<std::size_t>(offset.back())), fill(offset.begin(), offset.end() - 1);
  std::size_t k = 0;
  for (int r = 0; r < ranks; ++r)
    for (int i = 0; i < from[r]; ++i, ++k) holder[static_cast<std::size_t>(fill[asked[k] - lo]++)] = r;
  long long shared = 0;
  for (int n = 0; n < hi - lo; ++n) shared += offset[n + 1] - offset[n] > 1;
  // The answer to each source, in the order it asked: per node its holder count, then the holders.
  std::vector<int> reply, reply_count(static_cast<std::size_t>(ranks), 0);
  k = 0;
  for (int r = 0; r < ranks; ++r)
    for (int i = 0; i < from[r]; ++i, ++k) {
      const int n = asked[k] - lo;
      reply.push_back(offset[n + 1] - offset[n]);
      reply.insert(reply.end(), holder.begin() + offset[n], holder.begin() + offset[n + 1]);
      reply_count[r] += 1 + offset[n + 1] - offset[n];
    }
  std::vector<int> got;
  const std::vector<int> answer = exchange(reply_count, reply, got);
  p.holder_offset.assign(global_node.size() + 1, 0);
  p.holder_rank.clear();
  std::size_t at = 0;
  for (std::size_t l = 0; l < global_node.size(); ++l) {
    const int n = answer[at++];
    p.holder_rank.insert(p.holder_rank.end(), answer.begin() + static_cast<std::ptrdiff_t>(at),
                         answer.begin() + static_cast<std::ptrdiff_t>(at) + n);
    at += static_cast<std::size_t>(n);
    p.holder_offset[l + 1] = static_cast<int>(p.holder_rank.size());
  }
  MPI_Allreduce(MPI_IN_PLACE, &shared, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return shared;
}

}  // namespace

std::vector<int> PlanSource::slab_nodes() const {
  const std::vector<int> offset = slab_offsets(plan_.element_count, size());
  const int me = rank();
  return mesh::element_nodes(plan_, offset[me], offset[me + 1] - offset[me]);
}

std::vector<int> PlanSource::side_set_elements(const std::vector<std::string>& names) const {
  std::vector<int> elements;
  for (const auto& name : names)
    if (const auto it = plan_.side_sets.find(name); it != plan_.side_sets.end())
      for (const auto& side : it->second) elements.push_back(side.element);
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  return elements;
}

std::vector<int> contact_elements(const ElementSource& source, const inputs::ContactSpec& contact) {
  std::vector<std::string> names;
  for (const auto& s : contact.surfaces) names.insert(names.end(), s.side_sets.begin(), s.side_sets.end());
  return source.side_set_elements(names);
}

std::vector<int> slab_parts(const ElementSource& source) {
  const int ranks = size(), me = rank();
  const std::vector<int> offset = slab_offsets(source.element_count(), ranks);
  ElementSlab slab;
  slab.first = offset[me];
  slab.count = offset[me + 1] - offset[me];
  slab.nodes = source.slab_nodes();
  const DualGraphRows rows = face_dual_graph(slab);
  slab.nodes = {};
  return ptscotch_parts(rows, ranks);
}

void place_source_patches(const ElementSource& source, const inputs::ContactSpec* enforced,
                          std::vector<int>& slab_part, const AxisScale& scale) {
  const int ranks = size();
  if (!enforced || ranks <= 1) return;
  const std::vector<int> surface = contact_elements(source, *enforced);  // ascending
  const int first = slab_offsets(source.element_count(), ranks)[rank()];
  const int end = first + static_cast<int>(slab_part.size());
  std::vector<int> part(surface.size(), -1);  // each from the rank whose slab holds it
  for (std::size_t k = 0; k < surface.size(); ++k)
    if (surface[k] >= first && surface[k] < end) part[k] = slab_part[static_cast<std::size_t>(surface[k] - first)];
  MPI_Allreduce(MPI_IN_PLACE, part.data(), static_cast<int>(part.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  std::vector<int> global_node;
  place_contact_patches(source.elements_mesh(surface, global_node), enforced, ranks, part, scale);
  for (std::size_t k = 0; k < surface.size(); ++k)
    if (surface[k] >= first && surface[k] < end) slab_part[static_cast<std::size_t>(surface[k] - first)] = part[k];
}

SourcePart source_part(const ElementSource& source, std::vector<int> slab_part) {
  SourcePart g;
  MeshPart& p = g.part;
  p.global_element = partitioned_elements(source.element_count(), std::move(slab_part));
  p.mesh = source.elements_mesh(p.global_element, p.global_node);
  p.global_node_count = source.node_count();
  p.global_element_count = source.element_count();
  p.node_set_size = source.node_set_sizes();
  p.side_set_size = source.side_set_sizes();
  g.shared_nodes = fill_holders(p.global_node, source.node_count(), p);
  return g;
}

}  // namespace tribex::solver::parallel
