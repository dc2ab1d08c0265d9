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
      if (part.holder_rank[q] != rank) with[part.holder_rank[q]].push_back(static_cast<int>(halo_.shared_nodes.size()));
    halo_.shared_nodes.push_back(l);
  }
  halo_.neighbour_offset.push_back(0);
  for (int r = 0; r < ranks; ++r) {
    if (with[r].empty()) continue;
    halo_.neighbours.push_back(r);
    for (int slot : with[r]) {
      halo_.neighbour_nodes.push_back(halo_.shared_nodes[slot]);
      halo_.neighbour_slot.push_back(slot);
    }
    halo_.neighbour_offset.push_back(static_cast<int>(halo_.neighbour_nodes.size()));
  }
  halo_.size_buffers();
}

void Domain::Halo::size_buffers(int width) {
  const std::size_t w = static_cast<std::size_t>(width);
  send.assign(w * neighbour_nodes.size(), 0.0);
  recv.assign(w * neighbour_nodes.size(), 0.0);
  sum.assign(w * shared_nodes.size(), 0.0);
  requests.assign(2 * neighbours.size(), MPI_REQUEST_NULL);
}

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

void Domain::sum_shared(double* f, int width) {
  if (halo_.neighbours.empty()) return;
  ++traffic.halo_exchanges;
  sum_over(halo_, f, width, traffic.halo_sent, traffic.halo_received);
}

void Domain::sum_shared_surface(double* f, int width) {
  if (surface_halo_.neighbours.empty()) return;
  sum_over(surface_halo_, f, width, traffic.surface_sent, traffic.surface_received);
}

void Domain::sum_over(Halo& h, double* f, int width, long long& sent, long long& received) {
  const double start = now();
  const int nk = static_cast<int>(h.neighbours.size()), w = width;
  for (int k = 0; k < nk; ++k) {
    const int b = h.neighbour_offset[k], n = h.neighbour_offset[k + 1] - b;
    MPI_Irecv(&h.recv[w * b], w * n, MPI_DOUBLE, h.neighbours[k], 17, MPI_COMM_WORLD, &h.requests[k]);
    received += static_cast<long long>(sizeof(double)) * w * n;
  }
  for (int k = 0; k < nk; ++k) {
    const int b = h.neighbour_offset[k], n = h.neighbour_offset[k + 1] - b;
    for (int j = b; j < b + n; ++j)
      for (int i = 0; i < w; ++i) h.send[w * j + i] = f[w * h.neighbour_nodes[j] + i];
    MPI_Isend(&h.send[w * b], w * n, MPI_DOUBLE, h.neighbours[k], 17, MPI_COMM_WORLD, &h.requests[nk + k]);
    sent += static_cast<long long>(sizeof(double)) * w * n;
  }
  MPI_Waitall(2 * nk, h.requests.data(), MPI_STATUSES_IGNORE);
  // Sum in ascending rank order (0 + f_r1 + f_r2 + ...): the same operations on every rank that
  // holds the node, so all copies stay bit-identical.
  std::fill(h.sum.begin(), h.sum.end(), 0.0);
  bool mine_added = false;
  auto add_mine = [&]() {
    for (std::size_t s = 0; s < h.shared_nodes.size(); ++s)
      for (int i = 0; i < w; ++i) h.sum[w * s + i] += f[w * h.shared_nodes[s] + i];
    mine_added = true;
  };
  for (int k = 0; k < nk; ++k) {
    if (!mine_added && h.neighbours[k] > rank) add_mine();
    for (int j = h.neighbour_offset[k]; j < h.neighbour_offset[k + 1]; ++j)
      for (int i = 0; i < w; ++i) h.sum[w * h.neighbour_slot[j] + i] += h.recv[w * j + i];
  }
  if (!mine_added) add_mine();
  for (std::size_t s = 0; s < h.shared_nodes.size(); ++s)
    for (int i = 0; i < w; ++i) f[w * h.shared_nodes[s] + i] = h.sum[w * s + i];
  communication_seconds += now() - start;
}

int Domain::local_node(int global) const {
  const auto it = std::lower_bound(global_node.begin(), global_node.end(), global);
  return it != global_node.end() && *it == global ? static_cast<int>(it - global_node.begin()) : -1;
}

void Domain::set_surface(const std::vector<int>& surface_nodes) {
  const std::size_t ns = surface_nodes.size();
  surface_local_.assign(ns, -1);
  surface_owned_.assign(ns, 0.0);
  for (std::size_t k = 0; k < ns; ++k)
    if (const int l = local_node(surface_nodes[k]); l >= 0) {
      surface_local_[k] = l;
      surface_owned_[k] = owned[l];
    }
  // The halo restricted to the surface nodes (both sides keep the same order: ascending local node,
  // which is ascending global node on every rank).
  std::vector<char> on_surface(global_node.size(), 0);
  for (int l : surface_local_)
    if (l >= 0) on_surface[static_cast<std::size_t>(l)] = 1;
  Halo& h = surface_halo_;
  h = Halo{};
  std::vector<int> slot_of(halo_.shared_nodes.size(), -1);
  for (std::size_t s = 0; s < halo_.shared_nodes.size(); ++s)
    if (on_surface[static_cast<std::size_t>(halo_.shared_nodes[s])]) {
      slot_of[s] = static_cast<int>(h.shared_nodes.size());
      h.shared_nodes.push_back(halo_.shared_nodes[s]);
    }
  h.neighbour_offset.push_back(0);
  for (std::size_t k = 0; k < halo_.neighbours.size(); ++k) {
    const std::size_t before = h.neighbour_nodes.size();
    for (int j = halo_.neighbour_offset[k]; j < halo_.neighbour_offset[k + 1]; ++j)
      if (slot_of[static_cast<std::size_t>(halo_.neighbour_slot[j])] >= 0) {
        h.neighbour_nodes.push_back(halo_.neighbour_nodes[j]);
        h.neighbour_slot.push_back(slot_of[static_cast<std::size_t>(halo_.neighbour_slot[j])]);
      }
    if (h.neighbour_nodes.size() == before) continue;
    h.neighbours.push_back(halo_.neighbours[k]);
    h.neighbour_offset.push_back(static_cast<int>(h.neighbour_nodes.size()));
  }
  h.size_buffers(4);  // forces, and the tangential pairs' forces with master shares (ContactRegion)
}

bool Domain::shares_with(int local_node, int other_rank) const {
  const auto q = std::lower_bound(halo_.neighbours.begin(), halo_.neighbours.end(), other_rank);
  if (q == halo_.neighbours.end() || *q != other_rank) return false;
  const std::size_t k = static_cast<std::size_t>(q - halo_.neighbours.begin());
  const auto first = halo_.neighbour_nodes.begin() + halo_.neighbour_offset[k],
             last = halo_.neighbour_nodes.begin() + halo_.neighbour_offset[k + 1];
  return std::binary_search(first, last, local_node);
}

}  // namespace tribex::solver::parallel
