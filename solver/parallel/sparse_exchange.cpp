// SPDX-License-Identifier: MIT
#include "solver/parallel/sparse_exchange.hpp"

#include <mpi.h>

#include <cstddef>
#include <vector>

namespace tribex::solver::parallel {
namespace {

// Tags of this file's messages; no other message in tribex uses them (the halo's are 7, 8 and 17, the
// mesh parts' part_tag), and MPI keeps the order of messages between one pair with one tag, so two
// exchanges in a row match theirs in order.
constexpr int kCountTag = 5701;
constexpr int kValueTag = 5702;

// [world rank] != 0: this process has exchanged values with that rank (sparse_exchange_peers).
std::vector<char>& peers() {
  static std::vector<char> seen;
  return seen;
}

// Marks the ranks `of` of `comm` (world ranks through the groups when comm is a sub-communicator).
void remember(const std::vector<int>& of, MPI_Comm comm) {
  if (of.empty()) return;
  int world = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  auto& seen = peers();
  seen.resize(static_cast<std::size_t>(world), 0);
  std::vector<int> in_world(of);
  if (comm != MPI_COMM_WORLD) {
    MPI_Group group = MPI_GROUP_NULL, world_group = MPI_GROUP_NULL;
    MPI_Comm_group(comm, &group);
    MPI_Comm_group(MPI_COMM_WORLD, &world_group);
    MPI_Group_translate_ranks(group, static_cast<int>(of.size()), of.data(), world_group, in_world.data());
    MPI_Group_free(&group);
    MPI_Group_free(&world_group);
  }
  for (int r : in_world)
    if (r >= 0 && r < world) seen[static_cast<std::size_t>(r)] = 1;
}

}  // namespace

std::vector<int> sparse_counts(const std::vector<int>& count, MPI_Comm comm) {
  int ranks = 1, me = 0;
  MPI_Comm_size(comm, &ranks);
  MPI_Comm_rank(comm, &me);
  std::vector<int> received(static_cast<std::size_t>(ranks), 0);
  if (ranks == 1) {
    received[0] = count[0];
    return received;
  }
  // How many ranks send to this one: the sum over ranks of their 0/1 flag for it. A reduction, so no
  // rank leaves it before every rank has entered it, i.e. before every rank has received all of the
  // previous call's counts: a count of the next call cannot be taken for one of this call's.
  std::vector<int> sends(static_cast<std::size_t>(ranks), 0);
  for (int r = 0; r < ranks; ++r) sends[r] = count[r] > 0 && r != me ? 1 : 0;
  int senders = 0;
  MPI_Reduce_scatter_block(sends.data(), &senders, 1, MPI_INT, MPI_SUM, comm);
  std::vector<MPI_Request> requests;
  std::vector<int> to;
  for (int r = 0; r < ranks; ++r)
    if (sends[r]) {
      requests.emplace_back();
      to.push_back(r);
      MPI_Isend(&count[r], 1, MPI_INT, r, kCountTag, comm, &requests.back());
    }
  received[me] = count[me];
  for (int k = 0; k < senders; ++k) {
    int value = 0;
    MPI_Status status;
    MPI_Recv(&value, 1, MPI_INT, MPI_ANY_SOURCE, kCountTag, comm, &status);
    received[status.MPI_SOURCE] = value;
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  remember(to, comm);
  return received;
}

void sparse_alltoallv(const void* send, const int* send_count, const int* send_at, void* recv, const int* recv_count,
                      const int* recv_at, MPI_Datatype type, MPI_Comm comm) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  MPI_Aint lower = 0, extent = 0;
  MPI_Type_get_extent(type, &lower, &extent);
  const auto* out = static_cast<const char*>(send);
  auto* in = static_cast<char*>(recv);
  std::vector<MPI_Request> requests;
  std::vector<int> with;
  requests.reserve(2 * static_cast<std::size_t>(ranks));
  int me = 0;
  MPI_Comm_rank(comm, &me);
  // Receives first, so that the sends find them posted (no unexpected-message copies).
  for (int r = 0; r < ranks; ++r)
    if (recv_count[r] > 0) {
      requests.emplace_back();
      MPI_Irecv(in + static_cast<std::ptrdiff_t>(recv_at[r]) * extent, recv_count[r], type, r, kValueTag, comm,
                &requests.back());
      if (r != me) with.push_back(r);
    }
  for (int r = 0; r < ranks; ++r)
    if (send_count[r] > 0) {
      requests.emplace_back();
      MPI_Isend(out + static_cast<std::ptrdiff_t>(send_at[r]) * extent, send_count[r], type, r, kValueTag, comm,
                &requests.back());
      if (r != me) with.push_back(r);
    }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  remember(with, comm);
}

int sparse_exchange_peers() {
  int me = 0, initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) MPI_Comm_rank(MPI_COMM_WORLD, &me);
  int n = 0;
  const auto& seen = peers();
  for (std::size_t r = 0; r < seen.size(); ++r) n += seen[r] != 0 && static_cast<int>(r) != me;
  return n;
}

}  // namespace tribex::solver::parallel
