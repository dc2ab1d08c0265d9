// SPDX-License-Identifier: MIT
// The one way the ranks exchange runs of values with each other (issue 57): only the pairs that have
// something to say talk. MPI_Alltoall of the counts makes every rank message every other, and Open MPI's
// shared-memory transport (btl vader) then maps, and counts in the rank's RSS, the pages of every peer's
// segment it has read: about 0.73 MB per peer at 128 ranks on one node
// (docs/measurements/2026-11-29-output-memory.md, section 4), O(P) per rank at cluster scale in memory
// and time. Here a rank learns how many ranks will send to it with one MPI_Reduce_scatter_block of a 0/1
// "I send to you" vector (a reduction, whose tree or recursive-halving algorithms pair a rank with O(log P)
// others: at 64 ranks a rank had read from 12-13 peers when the set-up reached the partitioner,
// docs/measurements/2026-11-29-sparse-exchange.md), then the counts and the values travel point to point
// between the pairs with a nonzero count.
// Every receive lands at the offset the caller gives, so the result is what MPI_Alltoallv gives, bit for bit.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace tribex::solver::parallel {

/// Collective over `comm`: `count[r]` is what this rank sends rank r; returns what each rank sends this
/// one, `[r]` from rank r (MPI_Alltoall of one int, with messages only where count[r] > 0).
std::vector<int> sparse_counts(const std::vector<int>& count, MPI_Comm comm = MPI_COMM_WORLD);

/// Collective over `comm`: MPI_Alltoallv's arguments and result (counts and offsets in elements of `type`,
/// the same type both ways), with messages only between the pairs whose count is nonzero. Both sides'
/// counts must agree (sparse_counts gives the receive counts).
void sparse_alltoallv(const void* send, const int* send_count, const int* send_at, void* recv, const int* recv_count,
                      const int* recv_at, MPI_Datatype type, MPI_Comm comm = MPI_COMM_WORLD);

/// The ranks (of `comm`) this process has exchanged values with through the two calls above since it
/// started, this rank excluded: the peers whose shared-memory segments it has touched through them.
int sparse_exchange_peers();

template <class T>
MPI_Datatype mpi_type_of();
template <>
inline MPI_Datatype mpi_type_of<int>() { return MPI_INT; }
template <>
inline MPI_Datatype mpi_type_of<double>() { return MPI_DOUBLE; }

/// Collective over MPI_COMM_WORLD: `data` holds count[r] values for rank r in rank order; returns what
/// every rank sent this one in source-rank order, `received[r]` of them from rank r. Counts are ints
/// (MPI's): more than 2^31 values to one rank throws std::runtime_error on every rank alike.
template <class T>
std::vector<T> exchange(const std::vector<int>& count, const std::vector<T>& data, std::vector<int>& received) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  received = sparse_counts(count);
  std::vector<int> send_at(static_cast<std::size_t>(ranks) + 1, 0), recv_at(static_cast<std::size_t>(ranks) + 1, 0);
  long long total = 0;
  for (int r = 0; r < ranks; ++r) {
    send_at[r + 1] = send_at[r] + count[r];
    total += received[r];
    recv_at[r + 1] = static_cast<int>(std::min<long long>(total, INT32_MAX));
  }
  long long most = total;
  MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  if (most > INT32_MAX) throw std::runtime_error("the distributed set-up: more than 2^31 values to exchange on one rank");
  std::vector<T> recv(static_cast<std::size_t>(total));
  sparse_alltoallv(data.data(), count.data(), send_at.data(), recv.data(), received.data(), recv_at.data(),
                   mpi_type_of<T>());
  return recv;
}

/// The rank whose range of the even split `offset` (slab_offsets: [rank + 1]) holds `number`.
inline int home_of(const std::vector<int>& offset, int number) {
  return static_cast<int>(std::upper_bound(offset.begin(), offset.end(), number) - offset.begin() - 1);
}

}  // namespace tribex::solver::parallel
