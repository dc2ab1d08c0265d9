// SPDX-License-Identifier: MIT
#include "solver/parallel/contact_region.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "solver/parallel/domain.hpp"
#include "solver/parallel/sparse_exchange.hpp"
#include "solver/parallel/sparse_rows.hpp"

namespace tribex::solver::parallel {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

ContactRegion::ContactRegion(Domain& domain) : domain_(domain) {
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
  fill_send_offset_ = send_offset_;
  fill_recv_offset_ = recv_offset_;
  present_.assign(local.size(), 0);
  held_.assign(4 * domain.global_node.size(), 0.0);
  located_.reserve(64);
}

void ContactRegion::set_fields(contact::ContactManager::GhostFields fields) {
  fields_ = fields;
  row_values_ = 3 + (fields.velocity ? 3 : 0) + (fields.other_force ? 3 : 0);
  size_buffers();
}

ContactRegion::~ContactRegion() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (comm_ != MPI_COMM_NULL && !finalized) MPI_Comm_free(&comm_);
}

// A grid over the members' surface nodes with cells no smaller than half the reach, so that every
// node within the reach of a node lies within two cells of that node's cell (the 5 x 5 x 5 block);
// at most kMaxCells cells per axis (coarser cells only widen the region).
namespace {
constexpr int kMaxCells = 64;
constexpr int kReachCells = 2;  // the reach in cells
struct Grid {
  double lo[3] = {0, 0, 0};
  double cell = 1.0;
  int n[3] = {1, 1, 1};
  int index(const double* p, int dx = 0, int dy = 0, int dz = 0) const {
    const int d[3] = {dx, dy, dz};
    int c[3];
    for (int i = 0; i < 3; ++i) {
      c[i] = static_cast<int>(std::floor((p[i] - lo[i]) / cell)) + d[i];
      if (c[i] < 0 || c[i] >= n[i]) return -1;
    }
    return (c[2] * n[1] + c[1]) * n[0] + c[0];
  }
};
}  // namespace

void ContactRegion::refresh(const double* xg, contact::ContactManager& manager) {
  if (comm_ == MPI_COMM_NULL) return;  // no surface node here: an empty region
  const double start = now();
  const double reach = manager.region_reach();
  const auto& local = domain_.surface_local();
  const auto& owned = domain_.surface_owned();
  // The members' box (minima of the lower corner and of the negated upper one), then the grid.
  double box[6] = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
  for (std::size_t k = 0; k < local.size(); ++k)
    if (local[k] >= 0)
      for (int i = 0; i < 3; ++i) {
        box[i] = std::min(box[i], xg[3 * k + i]);
        box[3 + i] = std::min(box[3 + i], -xg[3 * k + i]);
      }
  MPI_Allreduce(MPI_IN_PLACE, box, 6, MPI_DOUBLE, MPI_MIN, comm_);
  Grid grid;
  double extent = 0.0;
  for (int i = 0; i < 3; ++i) {
    grid.lo[i] = box[i];
    extent = std::max(extent, -box[3 + i] - box[i]);
  }
  grid.cell = std::max(reach / kReachCells, extent / kMaxCells);
  if (!(grid.cell > 0.0)) grid.cell = 1.0;
  for (int i = 0; i < 3; ++i)
    grid.n[i] = std::clamp(static_cast<int>(std::floor((-box[3 + i] - box[i]) / grid.cell)) + 1, 1, kMaxCells + 1);
  const int cells = grid.n[0] * grid.n[1] * grid.n[2];
  const int words = (cells + 63) / 64;
  // Each member's box of the surface nodes its region grows from (ContactManager::seeds_region: in
  // owner-computes runs its counted slave nodes, else every node it holds), and the cells they occupy
  // (MPI_Allgather of a bit set).
  double held_box[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
  for (std::size_t k = 0; k < local.size(); ++k)
    if (local[k] >= 0 && manager.seeds_region(static_cast<int>(k)))
      for (int i = 0; i < 3; ++i) {
        held_box[i] = std::min(held_box[i], xg[3 * k + i]);
        held_box[3 + i] = std::max(held_box[3 + i], xg[3 * k + i]);
      }
  MPI_Allgather(held_box, 6, MPI_DOUBLE, boxes_.data(), 6, MPI_DOUBLE, comm_);
  // Scratch kept between refreshes: a refresh allocates only when the region grows.
  auto& mine = scratch_.mine;
  auto& occupied = scratch_.occupied;
  auto& around = scratch_.around;
  auto& owned_nodes = scratch_.owned_nodes;
  mine.assign(static_cast<std::size_t>(words), 0);
  occupied.assign(static_cast<std::size_t>(words) * members_, 0);
  for (std::size_t k = 0; k < local.size(); ++k)
    if (local[k] >= 0 && manager.seeds_region(static_cast<int>(k))) {
      const int c = grid.index(xg + 3 * k);
      mine[static_cast<std::size_t>(c) / 64] |= std::uint64_t{1} << (c % 64);
    }
  MPI_Allgather(mine.data(), words, MPI_UINT64_T, occupied.data(), words, MPI_UINT64_T, comm_);
  // The cells within the reach of each owned surface node (-1: outside the grid).
  constexpr int side = 2 * kReachCells + 1, block = side * side * side;
  around.clear();
  owned_nodes.clear();
  for (std::size_t k = 0; k < local.size(); ++k) {
    if (!(owned[k] > 0.0)) continue;
    owned_nodes.push_back(static_cast<int>(k));
    for (int dz = -kReachCells; dz <= kReachCells; ++dz)
      for (int dy = -kReachCells; dy <= kReachCells; ++dy)
        for (int dx = -kReachCells; dx <= kReachCells; ++dx) around.push_back(grid.index(xg + 3 * k, dx, dy, dz));
  }
  // Send lists: member by member, ascending surface node: the owned nodes within the reach of the
  // member's box and near a cell it occupies (each test alone takes in every node within the reach
  // of the member's nodes), unless it holds them itself.
  send_node_.clear();
  for (int q = 0; q < members_; ++q) {
    send_offset_[q] = static_cast<int>(send_node_.size());
    if (q == me_) continue;
    const std::uint64_t* bits = &occupied[static_cast<std::size_t>(words) * q];
    const double* b = &boxes_[6 * static_cast<std::size_t>(q)];
    for (std::size_t j = 0; j < owned_nodes.size(); ++j) {
      const int k = owned_nodes[j];
      const double* p = xg + 3 * k;
      bool near = true;
      for (int i = 0; i < 3; ++i) near = near && p[i] >= b[i] - reach && p[i] <= b[3 + i] + reach;
      bool occupied_near = false;
      for (int a = 0; a < block && near && !occupied_near; ++a) {
        const int c = around[static_cast<std::size_t>(block) * j + a];
        occupied_near = c >= 0 && (bits[c / 64] >> (c % 64) & 1U);
      }
      if (occupied_near && !domain_.shares_with(local[static_cast<std::size_t>(k)], world_rank_[q])) send_node_.push_back(k);
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
    exchange(width, send_offset_, recv_offset_);
    for (std::size_t j = 0; j < recv_node_.size(); ++j) manager.set_node_state(recv_node_[j], &recv_[width * j]);
    size_buffers();
  }
  domain_.communication_seconds += now() - start;
}

void ContactRegion::exchange_node_numbers() {
  const int n = members_;
  auto& send_count = scratch_.send_count;
  auto& recv_count = scratch_.recv_count;
  send_count.assign(static_cast<std::size_t>(n), 0);
  recv_count.assign(static_cast<std::size_t>(n), 0);
  for (int q = 0; q < n; ++q) send_count[q] = send_offset_[q + 1] - send_offset_[q];
  recv_count = sparse_counts(send_count, comm_);
  recv_offset_[0] = 0;
  for (int q = 0; q < n; ++q) recv_offset_[q + 1] = recv_offset_[q] + recv_count[q];
  recv_node_.assign(static_cast<std::size_t>(recv_offset_[n]), 0);
  sparse_alltoallv(send_node_.data(), send_count.data(), send_offset_.data(), recv_node_.data(), recv_count.data(),
                   recv_offset_.data(), MPI_INT, comm_);
}

void ContactRegion::size_buffers() {
  fill_every_row();
  const auto& local = domain_.surface_local();
  for (std::size_t k = 0; k < local.size(); ++k) present_[k] = local[k] >= 0;
  for (int k : recv_node_) present_[static_cast<std::size_t>(k)] = 1;
  send_.assign(static_cast<std::size_t>(row_values_) * send_node_.size(), 0.0);
  recv_.assign(static_cast<std::size_t>(row_values_) * recv_node_.size(), 0.0);
  rows_send_.assign((kMaxSumWidth + 1) * send_node_.size(), 0.0);
  rows_recv_.assign((kMaxSumWidth + 1) * recv_node_.size(), 0.0);
  requests_.reserve(2 * static_cast<std::size_t>(members_));
  rows_peer_.reserve(static_cast<std::size_t>(members_));
  statuses_.resize(2 * static_cast<std::size_t>(members_));
}

void ContactRegion::fill_every_row() {
  fill_send_offset_ = send_offset_;
  fill_recv_offset_ = recv_offset_;
  fill_send_node_.reserve(send_node_.size());  // trim's subsets fit without allocating
  fill_recv_node_.reserve(recv_node_.size());
  fill_send_node_.assign(send_node_.begin(), send_node_.end());
  fill_recv_node_.assign(recv_node_.begin(), recv_node_.end());
}

void ContactRegion::trim(const std::vector<char>& read) {
  if (comm_ == MPI_COMM_NULL) return;
  const double start = now();
  auto& keep = scratch_.recv_count;  // [member] ghost rows kept from it
  auto& give = scratch_.send_count;  // [member] rows it keeps of this rank's
  fill_recv_node_.clear();
  for (int q = 0; q < members_; ++q) {
    fill_recv_offset_[q] = static_cast<int>(fill_recv_node_.size());
    for (int j = recv_offset_[q]; j < recv_offset_[q + 1]; ++j)
      if (read[static_cast<std::size_t>(recv_node_[j])]) fill_recv_node_.push_back(recv_node_[j]);
    keep[q] = static_cast<int>(fill_recv_node_.size()) - fill_recv_offset_[q];
  }
  fill_recv_offset_[members_] = static_cast<int>(fill_recv_node_.size());
  give = sparse_counts(keep, comm_);
  fill_send_offset_[0] = 0;
  for (int q = 0; q < members_; ++q) fill_send_offset_[q + 1] = fill_send_offset_[q] + give[q];
  fill_send_node_.resize(static_cast<std::size_t>(fill_send_offset_[members_]));
  sparse_alltoallv(fill_recv_node_.data(), keep.data(), fill_recv_offset_.data(), fill_send_node_.data(), give.data(),
                   fill_send_offset_.data(), MPI_INT, comm_);
  domain_.communication_seconds += now() - start;
}

void ContactRegion::exchange(int width, const std::vector<int>& send_offset, const std::vector<int>& recv_offset) {
  requests_.clear();
  for (int q = 0; q < members_; ++q) {
    const int count = recv_offset[q + 1] - recv_offset[q];
    if (count == 0) continue;
    requests_.emplace_back();
    MPI_Irecv(recv_.data() + static_cast<std::size_t>(width) * recv_offset[q], width * count, MPI_DOUBLE, q, 7, comm_,
              &requests_.back());
  }
  for (int q = 0; q < members_; ++q) {
    const int count = send_offset[q + 1] - send_offset[q];
    if (count == 0) continue;
    requests_.emplace_back();
    MPI_Isend(send_.data() + static_cast<std::size_t>(width) * send_offset[q], width * count, MPI_DOUBLE, q, 7, comm_,
              &requests_.back());
  }
  MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
}

void ContactRegion::exchange_rows(double* values, int width, bool reverse) {
  const std::size_t stride = static_cast<std::size_t>(width) + 1;
  const std::vector<int>& out_node = reverse ? recv_node_ : send_node_;
  const std::vector<int>& in_node = reverse ? send_node_ : recv_node_;
  const std::vector<int>& out_offset = reverse ? recv_offset_ : send_offset_;
  const std::vector<int>& in_offset = reverse ? send_offset_ : recv_offset_;
  double* out = reverse ? rows_recv_.data() : rows_send_.data();
  double* in = reverse ? rows_send_.data() : rows_recv_.data();
  requests_.clear();
  rows_peer_.clear();
  for (int q = 0; q < members_; ++q) {
    const int count = in_offset[q + 1] - in_offset[q];
    if (count == 0) continue;
    requests_.emplace_back();
    rows_peer_.push_back(q);
    MPI_Irecv(in + stride * in_offset[q], static_cast<int>(stride) * count, MPI_DOUBLE, q, 8, comm_, &requests_.back());
  }
  const std::size_t receives = requests_.size();
  long long sent = 0;
  for (int q = 0; q < members_; ++q) {
    const int first = out_offset[q], count = out_offset[q + 1] - first;
    if (count == 0) continue;
    double* message = out + stride * first;
    const int length = pack_nonzero_rows(values, width, out_node.data() + first, count, message);
    sent += length;
    requests_.emplace_back();
    MPI_Isend(message, length, MPI_DOUBLE, q, 8, comm_, &requests_.back());
  }
  MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), statuses_.data());
  long long received = 0;
  for (std::size_t r = 0; r < receives; ++r) {
    const int q = rows_peer_[r], first = in_offset[q], count = in_offset[q + 1] - first;
    int length = 0;
    MPI_Get_count(&statuses_[r], MPI_DOUBLE, &length);
    received += length;
    apply_rows(in + stride * first, length, width, in_node.data() + first, count, values, reverse);
  }
  domain_.traffic.surface_sent += static_cast<long long>(sizeof(double)) * sent;
  domain_.traffic.surface_received += static_cast<long long>(sizeof(double)) * received;
}

void ContactRegion::sum_to_holders(double* values, int width) {
  if (width > kMaxSumWidth)
    throw std::logic_error("ContactRegion::sum_to_holders: " + std::to_string(width) + " values a node, at most " +
                           std::to_string(kMaxSumWidth));
  const std::size_t w = static_cast<std::size_t>(width);
  if (comm_ != MPI_COMM_NULL) {
    const double start = now();
    exchange_rows(values, width, true);
    domain_.communication_seconds += now() - start;
  }
  // The shared surface nodes, in the domain's numbering (the halo sum's).
  const auto& local = domain_.surface_local();
  for (std::size_t k = 0; k < local.size(); ++k)
    if (const int l = local[k]; l >= 0)
      for (std::size_t i = 0; i < w; ++i) held_[w * l + i] = values[w * k + i];
  domain_.sum_shared_surface(held_.data(), width);
  for (std::size_t k = 0; k < local.size(); ++k)
    if (const int l = local[k]; l >= 0)
      for (std::size_t i = 0; i < w; ++i) values[w * k + i] = held_[w * l + i];
}

void ContactRegion::complete_node_sums(double* values, int width) {
  sum_to_holders(values, width);
  if (comm_ == MPI_COMM_NULL) return;
  const double start = now();
  exchange_rows(values, width, false);
  domain_.communication_seconds += now() - start;
}

void ContactRegion::fill_ghosts(double* xg, double* vg, double* fg) {
  if (comm_ == MPI_COMM_NULL) return;
  const double start = now();
  // A row: x, then v and f where the passes read them.
  const std::size_t K = static_cast<std::size_t>(row_values_);
  double* fields[3] = {xg, fields_.velocity ? vg : nullptr, fields_.other_force ? fg : nullptr};
  for (std::size_t j = 0; j < fill_send_node_.size(); ++j) {
    const std::size_t k = static_cast<std::size_t>(fill_send_node_[j]);
    double* row = &send_[K * j];
    for (const double* field : fields)
      if (field)
        for (int i = 0; i < 3; ++i) *row++ = field[3 * k + i];
  }
  exchange(row_values_, fill_send_offset_, fill_recv_offset_);
  for (std::size_t j = 0; j < fill_recv_node_.size(); ++j) {
    const std::size_t k = static_cast<std::size_t>(fill_recv_node_[j]);
    const double* row = &recv_[K * j];
    for (double* field : fields)
      if (field)
        for (int i = 0; i < 3; ++i) field[3 * k + i] = *row++;
  }
  ++domain_.traffic.surface_gathers;
  domain_.traffic.surface_sent += static_cast<long long>(sizeof(double) * K * fill_send_node_.size());
  domain_.traffic.surface_received += static_cast<long long>(sizeof(double) * K * fill_recv_node_.size());
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
