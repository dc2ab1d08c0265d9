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
  surface_nodes_ = surface_nodes;
  const std::size_t ns = surface_nodes.size();
  surface_local_.assign(ns, -1);
  surface_owned_.assign(ns, 0.0);
  surface_send_index_.clear();
  // local index of a global node: global_node is ascending
  for (std::size_t k = 0; k < ns; ++k) {
    auto it = std::lower_bound(global_node.begin(), global_node.end(), surface_nodes[k]);
    if (it != global_node.end() && *it == surface_nodes[k]) {
      const int l = static_cast<int>(it - global_node.begin());
      surface_local_[k] = l;
      surface_owned_[k] = owned[l];
      if (owned[l] > 0.0) surface_send_index_.push_back(l);
    }
  }
  // The gathered buffer holds each rank's owned surface nodes in turn, ascending k within a rank.
  std::vector<int> mine;
  for (std::size_t k = 0; k < ns; ++k)
    if (surface_owned_[k] > 0.0) mine.push_back(static_cast<int>(k));
  surface_counts_.assign(static_cast<std::size_t>(ranks), 0);
  surface_displs_.assign(static_cast<std::size_t>(ranks), 0);
  surface_order_ = mine;
  if (!serial()) {
    std::vector<int> count(static_cast<std::size_t>(ranks)), at(static_cast<std::size_t>(ranks), 0);
    int n_mine = static_cast<int>(mine.size());
    MPI_Allgather(&n_mine, 1, MPI_INT, count.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (int r = 1; r < ranks; ++r) at[r] = at[r - 1] + count[r - 1];
    surface_order_.assign(static_cast<std::size_t>(at.back() + count.back()), 0);
    MPI_Allgatherv(mine.data(), n_mine, MPI_INT, surface_order_.data(), count.data(), at.data(), MPI_INT, MPI_COMM_WORLD);
    for (int r = 0; r < ranks; ++r) {
      surface_counts_[r] = kSurfaceValues * count[r];
      surface_displs_[r] = kSurfaceValues * at[r];
    }
  }
  if (surface_order_.size() != ns) throw std::logic_error("surface ownership disagrees between ranks");
  surface_send_.assign(kSurfaceValues * surface_send_index_.size(), 0.0);
  surface_recv_.assign(kSurfaceValues * ns, 0.0);
}

void Domain::gather_surface(const double* x, const double* v, const double* f, double* xg, double* vg, double* fg) {
  if (serial()) {
    for (std::size_t k = 0; k < surface_nodes_.size(); ++k) {
      const int node = surface_nodes_[k];
      for (int i = 0; i < 3; ++i) {
        xg[3 * k + i] = x[3 * node + i];
        vg[3 * k + i] = v[3 * node + i];
        fg[3 * k + i] = f[3 * node + i];
      }
    }
    return;
  }
  const double start = now();
  constexpr int K = kSurfaceValues;
  for (std::size_t j = 0; j < surface_send_index_.size(); ++j) {
    const int l = surface_send_index_[j];
    for (int i = 0; i < 3; ++i) {
      surface_send_[K * j + i] = x[3 * l + i];
      surface_send_[K * j + 3 + i] = v[3 * l + i];
      surface_send_[K * j + 6 + i] = f[3 * l + i];
    }
  }
  MPI_Allgatherv(surface_send_.data(), static_cast<int>(surface_send_.size()), MPI_DOUBLE, surface_recv_.data(),
                 surface_counts_.data(), surface_displs_.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  ++traffic.surface_gathers;
  const long long mine = static_cast<long long>(sizeof(double) * surface_send_.size());
  traffic.surface_sent += mine * (ranks - 1);
  traffic.surface_received += static_cast<long long>(sizeof(double) * surface_recv_.size()) - mine;
  for (std::size_t j = 0; j < surface_order_.size(); ++j) {
    const std::size_t k = static_cast<std::size_t>(surface_order_[j]);
    for (int i = 0; i < 3; ++i) {
      xg[3 * k + i] = surface_recv_[K * j + i];
      vg[3 * k + i] = surface_recv_[K * j + 3 + i];
      fg[3 * k + i] = surface_recv_[K * j + 6 + i];
    }
  }
  communication_seconds += now() - start;
}

}  // namespace tribex::solver::parallel
