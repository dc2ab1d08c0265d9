// SPDX-License-Identifier: MIT
// One MPI_Alltoallv of plain values, the message of the distributed set-up's exchanges (source_parts.cpp,
// file_slice_source.cpp): every rank sends each rank a run of values and receives theirs in source-rank order.
#pragma once

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace tribex::solver::parallel {

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
  if (most > INT32_MAX) throw std::runtime_error("the distributed set-up: more than 2^31 values to exchange on one rank");
  std::vector<T> recv(static_cast<std::size_t>(total));
  MPI_Alltoallv(data.data(), count.data(), send_at.data(), mpi_type_of<T>(), recv.data(), received.data(),
                recv_at.data(), mpi_type_of<T>(), MPI_COMM_WORLD);
  return recv;
}

/// The rank whose range of the even split `offset` (slab_offsets: [rank + 1]) holds `number`.
inline int home_of(const std::vector<int>& offset, int number) {
  return static_cast<int>(std::upper_bound(offset.begin(), offset.end(), number) - offset.begin() - 1);
}

}  // namespace tribex::solver::parallel
