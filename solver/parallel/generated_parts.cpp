// SPDX-License-Identifier: MIT
#include "solver/parallel/generated_parts.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "solver/parallel/communicator.hpp"
#include "solver/parallel/contact_partition.hpp"
#include "solver/parallel/element_slab.hpp"
#include "solver/parallel/face_dual_graph.hpp"
#include "solver/parallel/ptscotch_partition.hpp"

namespace tribex::solver::parallel {
namespace {

// MPI_Alltoallv of ints: `data` holds count[r] ints for rank r in rank order; returns what every rank
// sent this one in source-rank order, `received[r]` of them from rank r. Counts are ints (MPI's).
std::vector<int> exchange(const std::vector<int>& count, const std::vector<int>& data, std::vector<int>& received) {
  const int ranks = size();
  received.assign(static_cast<std::size_t>(ranks), 0);
  MPI_Alltoall(count.data(), 1, MPI_INT, received.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::vector<int> send_at(static_cast<std::size_t>(ranks) + 1, 0), recv_at(static_cast<std::size_t>(ranks) + 1, 0);
  long long total = 0;
  for (int r = 0; r < ranks; ++r) {
    send_at[r + 1] = send_at[r] + count[r];
    total += received[r];
    recv_at[r + 1] = static_cast<int>(std::min<long long>(total, INT32_MAX));
  }
  long long most = total;
  MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  if (most > INT32_MAX) throw std::runtime_error("generated_part: more than 2^31 ints to exchange on one rank");
  std::vector<int> recv(static_cast<std::size_t>(total));
  MPI_Alltoallv(data.data(), count.data(), send_at.data(), MPI_INT, recv.data(), received.data(), recv_at.data(),
                MPI_INT, MPI_COMM_WORLD);
  return recv;
}

// Step 3: this rank's elements (global numbers, ascending) under the partition of the slabs.
std::vector<int> partitioned_elements(const mesh::GeneratedPlan& plan, std::vector<int> part) {
  const int ranks = size(), me = rank();
  const int first = slab_offsets(plan.element_count, ranks)[me];
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
  for (int n : global_node)
    ++count[static_cast<std::size_t>(std::upper_bound(home_offset.begin(), home_offset.end(), n) - home_offset.begin() - 1)];
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

std::vector<int> generated_slab_parts(const mesh::GeneratedPlan& plan) {
  const int ranks = size(), me = rank();
  const std::vector<int> offset = slab_offsets(plan.element_count, ranks);
  ElementSlab slab;
  slab.first = offset[me];
  slab.count = offset[me + 1] - offset[me];
  slab.nodes = mesh::element_nodes(plan, slab.first, slab.count);
  const DualGraphRows rows = face_dual_graph(slab);
  slab.nodes = {};
  return ptscotch_parts(rows, ranks);
}

void place_generated_patches(const mesh::GeneratedPlan& plan, const inputs::ContactSpec* enforced,
                             std::vector<int>& slab_part, const AxisScale& scale) {
  const int ranks = size();
  if (!enforced || ranks <= 1) return;
  std::vector<int> surface;  // the contact surfaces' elements, ascending
  for (const auto& s : enforced->surfaces)
    for (const auto& set : s.side_sets)
      if (const auto it = plan.side_sets.find(set); it != plan.side_sets.end())
        for (const auto& side : it->second) surface.push_back(side.element);
  std::sort(surface.begin(), surface.end());
  surface.erase(std::unique(surface.begin(), surface.end()), surface.end());
  const int first = slab_offsets(plan.element_count, ranks)[rank()];
  const int end = first + static_cast<int>(slab_part.size());
  std::vector<int> part(surface.size(), -1);  // each from the rank whose slab holds it
  for (std::size_t k = 0; k < surface.size(); ++k)
    if (surface[k] >= first && surface[k] < end) part[k] = slab_part[static_cast<std::size_t>(surface[k] - first)];
  MPI_Allreduce(MPI_IN_PLACE, part.data(), static_cast<int>(part.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  std::vector<int> global_node;
  place_contact_patches(mesh::generate_elements(plan, surface, global_node), enforced, ranks, part, scale);
  for (std::size_t k = 0; k < surface.size(); ++k)
    if (surface[k] >= first && surface[k] < end) slab_part[static_cast<std::size_t>(surface[k] - first)] = part[k];
}

GeneratedPart generated_part(const mesh::GeneratedPlan& plan, std::vector<int> slab_part) {
  GeneratedPart g;
  MeshPart& p = g.part;
  p.global_element = partitioned_elements(plan, std::move(slab_part));
  p.mesh = mesh::generate_elements(plan, p.global_element, p.global_node);
  p.global_node_count = plan.node_count;
  p.global_element_count = plan.element_count;
  p.node_set_size = plan.node_set_sizes();
  p.side_set_size = plan.side_set_sizes();
  g.shared_nodes = fill_holders(p.global_node, plan.node_count, p);
  return g;
}

}  // namespace tribex::solver::parallel
