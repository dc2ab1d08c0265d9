// SPDX-License-Identifier: MIT
#include "solver/parallel/domain.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "solver/parallel/communicator.hpp"
#include "solver/parallel/mesh_part.hpp"

namespace tribex::solver::parallel {

void Domain::init_serial(int nodes, int elements) {
  rank = 0;
  ranks = 1;
  global_node_count = nodes;
  global_element_count = elements;
  global_node.resize(static_cast<std::size_t>(nodes));
  std::iota(global_node.begin(), global_node.end(), 0);
  global_element.resize(static_cast<std::size_t>(elements));
  std::iota(global_element.begin(), global_element.end(), 0);
  owned.assign(static_cast<std::size_t>(nodes), 1.0);
  owned_nodes_ = nodes;
  owned_local_nodes_ = global_node;
}

void Domain::init_parallel(const MeshPart& part) {
  rank = parallel::rank();
  ranks = parallel::size();
  global_node_count = part.global_node_count;
  global_element_count = part.global_element_count;
  global_node = part.global_node;
  global_element = part.global_element;
  const int ln = static_cast<int>(global_node.size());
  owned.assign(static_cast<std::size_t>(ln), 0.0);
  // Owned by the lowest holder; halo lists: for every neighbour rank the shared local nodes, ascending.
  std::vector<std::vector<int>> with(static_cast<std::size_t>(ranks));
  for (int l = 0; l < ln; ++l) {
    const int first = part.holder_offset[l], last = part.holder_offset[l + 1];
    if (part.holder_rank[first] == rank) {
      owned[l] = 1.0;
      ++owned_nodes_;
      owned_local_nodes_.push_back(l);
    }
    if (last - first < 2) continue;
    for (int q = first; q < last; ++q)
      if (part.holder_rank[q] != rank) with[part.holder_rank[q]].push_back(static_cast<int>(shared_nodes_.size()));
    shared_nodes_.push_back(l);
  }
  neighbour_offset_.push_back(0);
  for (int r = 0; r < ranks; ++r) {
    if (with[r].empty()) continue;
    neighbours_.push_back(r);
    for (int slot : with[r]) {
      neighbour_nodes_.push_back(shared_nodes_[slot]);
      neighbour_slot_.push_back(slot);
    }
    neighbour_offset_.push_back(static_cast<int>(neighbour_nodes_.size()));
  }
  send_.assign(3 * neighbour_nodes_.size(), 0.0);
  recv_.assign(3 * neighbour_nodes_.size(), 0.0);
  sum_.assign(3 * shared_nodes_.size(), 0.0);
  requests_.assign(2 * neighbours_.size(), MPI_REQUEST_NULL);
}

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

void Domain::sum_shared(double* f, int width) {
  if (neighbours_.empty()) return;
  const double start = now();
  const int nk = static_cast<int>(neighbours_.size()), w = width;
  ++traffic.halo_exchanges;
  for (int k = 0; k < nk; ++k) {
    const int b = neighbour_offset_[k], n = neighbour_offset_[k + 1] - b;
    MPI_Irecv(&recv_[w * b], w * n, MPI_DOUBLE, neighbours_[k], 17, MPI_COMM_WORLD, &requests_[k]);
    traffic.halo_received += static_cast<long long>(sizeof(double)) * w * n;
  }
  for (int k = 0; k < nk; ++k) {
    const int b = neighbour_offset_[k], n = neighbour_offset_[k + 1] - b;
    for (int j = b; j < b + n; ++j)
      for (int i = 0; i < w; ++i) send_[w * j + i] = f[w * neighbour_nodes_[j] + i];
    MPI_Isend(&send_[w * b], w * n, MPI_DOUBLE, neighbours_[k], 17, MPI_COMM_WORLD, &requests_[nk + k]);
    traffic.halo_sent += static_cast<long long>(sizeof(double)) * w * n;
  }
  MPI_Waitall(2 * nk, requests_.data(), MPI_STATUSES_IGNORE);
  // Sum in ascending rank order (0 + f_r1 + f_r2 + ...): the same operations on every rank that
  // holds the node, so all copies stay bit-identical.
  std::fill(sum_.begin(), sum_.end(), 0.0);
  bool mine_added = false;
  auto add_mine = [&]() {
    for (std::size_t s = 0; s < shared_nodes_.size(); ++s)
      for (int i = 0; i < w; ++i) sum_[w * s + i] += f[w * shared_nodes_[s] + i];
    mine_added = true;
  };
  for (int k = 0; k < nk; ++k) {
    if (!mine_added && neighbours_[k] > rank) add_mine();
    for (int j = neighbour_offset_[k]; j < neighbour_offset_[k + 1]; ++j)
      for (int i = 0; i < w; ++i) sum_[w * neighbour_slot_[j] + i] += recv_[w * j + i];
  }
  if (!mine_added) add_mine();
  for (std::size_t s = 0; s < shared_nodes_.size(); ++s)
    for (int i = 0; i < w; ++i) f[w * shared_nodes_[s] + i] = sum_[w * s + i];
  communication_seconds += now() - start;
}

void Domain::set_surface(const std::vector<int>& surface_nodes) {
  const std::size_t ns = surface_nodes.size();
  surface_local_.assign(ns, -1);
  surface_owned_.assign(ns, 0.0);
  // local index of a global node: global_node is ascending
  for (std::size_t k = 0; k < ns; ++k) {
    auto it = std::lower_bound(global_node.begin(), global_node.end(), surface_nodes[k]);
    if (it != global_node.end() && *it == surface_nodes[k]) {
      const int l = static_cast<int>(it - global_node.begin());
      surface_local_[k] = l;
      surface_owned_[k] = owned[l];
    }
  }
}

bool Domain::shares_with(int local_node, int other_rank) const {
  const auto q = std::lower_bound(neighbours_.begin(), neighbours_.end(), other_rank);
  if (q == neighbours_.end() || *q != other_rank) return false;
  const std::size_t k = static_cast<std::size_t>(q - neighbours_.begin());
  const auto first = neighbour_nodes_.begin() + neighbour_offset_[k], last = neighbour_nodes_.begin() + neighbour_offset_[k + 1];
  return std::binary_search(first, last, local_node);
}

}  // namespace tribex::solver::parallel
