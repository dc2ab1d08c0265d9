// SPDX-License-Identifier: MIT
#include "solver/parallel/contact_region.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "solver/parallel/domain.hpp"

namespace tribex::solver::parallel {

namespace {
constexpr int kRowValues = 9;  // x, v, f of a ghost row
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

ContactRegion::ContactRegion(Domain& domain, double reach) : domain_(domain), reach_(reach) {
  const auto& local = domain.surface_local();
  const bool holds_surface = std::any_of(local.begin(), local.end(), [](int l) { return l >= 0; });
  MPI_Comm_split(MPI_COMM_WORLD, holds_surface ? 0 : MPI_UNDEFINED, domain.rank, &comm_);
  if (comm_ != MPI_COMM_NULL) {
    MPI_Comm_size(comm_, &members_);
    MPI_Comm_rank(comm_, &me_);
    world_rank_.assign(static_cast<std::size_t>(members_), 0);
    MPI_Allgather(&domain.rank, 1, MPI_INT, world_rank_.data(), 1, MPI_INT, comm_);
  }
  boxes_.assign(6 * static_cast<std::size_t>(members_), 0.0);
  send_offset_.assign(static_cast<std::size_t>(members_) + 1, 0);
  recv_offset_.assign(static_cast<std::size_t>(members_) + 1, 0);
  present_.assign(local.size(), 0);
  located_.reserve(64);
}

ContactRegion::~ContactRegion() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (comm_ != MPI_COMM_NULL && !finalized) MPI_Comm_free(&comm_);
}

void ContactRegion::refresh(const double* xg, contact::ContactManager& manager) {
  if (comm_ == MPI_COMM_NULL) return;  // no surface node here: an empty region
  const double start = now();
  const auto& local = domain_.surface_local();
  const auto& owned = domain_.surface_owned();
  double box[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
  for (std::size_t k = 0; k < local.size(); ++k)
    if (local[k] >= 0)
      for (int i = 0; i < 3; ++i) {
        box[i] = std::min(box[i], xg[3 * k + i]);
        box[3 + i] = std::max(box[3 + i], xg[3 * k + i]);
      }
  MPI_Allgather(box, 6, MPI_DOUBLE, boxes_.data(), 6, MPI_DOUBLE, comm_);
  // Send lists: member by member, ascending surface node.
  send_node_.clear();
  for (int q = 0; q < members_; ++q) {
    send_offset_[q] = static_cast<int>(send_node_.size());
    const double* b = &boxes_[6 * static_cast<std::size_t>(q)];
    if (q == me_) continue;
    for (std::size_t k = 0; k < local.size(); ++k) {
      if (!(owned[k] > 0.0) || domain_.shares_with(local[k], world_rank_[q])) continue;
      const double* p = xg + 3 * k;
      bool inside = true;
      for (int i = 0; i < 3; ++i) inside = inside && p[i] >= b[i] - reach_ && p[i] <= b[3 + i] + reach_;
      if (inside) send_node_.push_back(static_cast<int>(k));
    }
  }
  send_offset_[members_] = static_cast<int>(send_node_.size());
  exchange_node_numbers();
  size_buffers();
  // The laws' state of the nodes entering the other ranks' regions: the owner's.
  const int width = manager.node_state_width();
  if (width > 0) {
    send_.resize(static_cast<std::size_t>(width) * send_node_.size());
    recv_.resize(static_cast<std::size_t>(width) * recv_node_.size());
    for (std::size_t j = 0; j < send_node_.size(); ++j) manager.get_node_state(send_node_[j], &send_[width * j]);
    exchange(width);
    for (std::size_t j = 0; j < recv_node_.size(); ++j) manager.set_node_state(recv_node_[j], &recv_[width * j]);
    size_buffers();
  }
  domain_.communication_seconds += now() - start;
}

void ContactRegion::exchange_node_numbers() {
  const int n = members_;
  std::vector<int> send_count(static_cast<std::size_t>(n)), recv_count(static_cast<std::size_t>(n));
  for (int q = 0; q < n; ++q) send_count[q] = send_offset_[q + 1] - send_offset_[q];
  MPI_Alltoall(send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, comm_);
  recv_offset_[0] = 0;
  for (int q = 0; q < n; ++q) recv_offset_[q + 1] = recv_offset_[q] + recv_count[q];
  recv_node_.assign(static_cast<std::size_t>(recv_offset_[n]), 0);
  MPI_Alltoallv(send_node_.data(), send_count.data(), send_offset_.data(), MPI_INT, recv_node_.data(),
                recv_count.data(), recv_offset_.data(), MPI_INT, comm_);
}

void ContactRegion::size_buffers() {
  const auto& local = domain_.surface_local();
  for (std::size_t k = 0; k < local.size(); ++k) present_[k] = local[k] >= 0;
  for (int k : recv_node_) present_[static_cast<std::size_t>(k)] = 1;
  send_.assign(kRowValues * send_node_.size(), 0.0);
  recv_.assign(kRowValues * recv_node_.size(), 0.0);
  requests_.reserve(2 * static_cast<std::size_t>(members_));
}

void ContactRegion::exchange(int width) {
  requests_.clear();
  for (int q = 0; q < members_; ++q) {
    const int count = recv_offset_[q + 1] - recv_offset_[q];
    if (count == 0) continue;
    requests_.emplace_back();
    MPI_Irecv(&recv_[static_cast<std::size_t>(width) * recv_offset_[q]], width * count, MPI_DOUBLE, q, 7, comm_,
              &requests_.back());
  }
  for (int q = 0; q < members_; ++q) {
    const int count = send_offset_[q + 1] - send_offset_[q];
    if (count == 0) continue;
    requests_.emplace_back();
    MPI_Isend(&send_[static_cast<std::size_t>(width) * send_offset_[q]], width * count, MPI_DOUBLE, q, 7, comm_,
              &requests_.back());
  }
  MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
}

void ContactRegion::fill_ghosts(double* xg, double* vg, double* fg) {
  if (comm_ == MPI_COMM_NULL) return;
  const double start = now();
  constexpr int K = kRowValues;
  for (std::size_t j = 0; j < send_node_.size(); ++j) {
    const std::size_t k = static_cast<std::size_t>(send_node_[j]);
    for (int i = 0; i < 3; ++i) {
      send_[K * j + i] = xg[3 * k + i];
      send_[K * j + 3 + i] = vg[3 * k + i];
      send_[K * j + 6 + i] = fg[3 * k + i];
    }
  }
  exchange(K);
  for (std::size_t j = 0; j < recv_node_.size(); ++j) {
    const std::size_t k = static_cast<std::size_t>(recv_node_[j]);
    for (int i = 0; i < 3; ++i) {
      xg[3 * k + i] = recv_[K * j + i];
      vg[3 * k + i] = recv_[K * j + 3 + i];
      fg[3 * k + i] = recv_[K * j + 6 + i];
    }
  }
  ++domain_.traffic.surface_gathers;
  domain_.traffic.surface_sent += static_cast<long long>(sizeof(double) * send_.size());
  domain_.traffic.surface_received += static_cast<long long>(sizeof(double) * recv_.size());
  domain_.communication_seconds += now() - start;
}

std::vector<int> ContactRegion::lists() const {
  std::vector<int> out(send_offset_);
  out.insert(out.end(), send_node_.begin(), send_node_.end());
  return out;
}

void ContactRegion::restore_lists(const std::vector<int>& lists) {
  if (comm_ == MPI_COMM_NULL) return;
  const std::size_t n = static_cast<std::size_t>(members_) + 1;
  if (lists.size() < n || lists.size() != n + static_cast<std::size_t>(lists[n - 1]))
    throw std::invalid_argument("the contact region lists do not fit this run's ranks");
  send_offset_.assign(lists.begin(), lists.begin() + static_cast<std::ptrdiff_t>(n));
  send_node_.assign(lists.begin() + static_cast<std::ptrdiff_t>(n), lists.end());
  exchange_node_numbers();
  size_buffers();
}

void ContactRegion::sum(double* values, int count) {
  MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

void ContactRegion::max(double* values, int count) {
  MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

void ContactRegion::max_at(double* values, int* nodes, int count) {
  located_.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) located_[i] = {values[i], nodes[i]};
  MPI_Allreduce(MPI_IN_PLACE, located_.data(), count, MPI_DOUBLE_INT, MPI_MAXLOC, MPI_COMM_WORLD);
  for (int i = 0; i < count; ++i) {
    values[i] = located_[i].value;
    nodes[i] = located_[i].node;
  }
}

}  // namespace tribex::solver::parallel
