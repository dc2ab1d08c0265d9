// SPDX-License-Identifier: MIT
#include "solver/output/row_blocks.hpp"

#include "solver/parallel/sparse_exchange.hpp"

#include <mpi.h>

#include <cstring>
#include <limits>
#include <stdexcept>

namespace tribex::solver::output {
namespace {

int world_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

int world_rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// Offsets of per-rank counts: at[r] = count[0] + ... + count[r - 1]; ints, as MPI's counts are.
std::vector<int> offsets(const std::vector<int>& count) {
  std::vector<int> at(count.size() + 1, 0);
  long long total = 0;
  for (std::size_t r = 0; r < count.size(); ++r) {
    total += count[r];
    if (total > std::numeric_limits<int>::max()) throw std::runtime_error("results.h5: more than 2^31 rows on one rank");
    at[r + 1] = static_cast<int>(total);
  }
  return at;
}

}  // namespace

std::vector<unsigned long long> RowBlocks::split(unsigned long long rows, unsigned long long align, int ranks) {
  // Whole chunks per rank, as even as they go (the last chunk may be short): rank r starts at chunk
  // floor(r C / N) of C chunks.
  const unsigned long long a = align == 0 ? 1 : align, chunks = (rows + a - 1) / a;
  std::vector<unsigned long long> bounds(static_cast<std::size_t>(ranks) + 1);
  for (int r = 0; r <= ranks; ++r)
    bounds[static_cast<std::size_t>(r)] = std::min(rows, chunks * static_cast<unsigned long long>(r) / ranks * a);
  return bounds;
}

RowBlocks::RowBlocks(const std::vector<std::array<unsigned long long, 2>>& runs, unsigned long long rows,
                     unsigned long long align) {
  const int n = world_size();
  const std::vector<unsigned long long> bounds = split(rows, align, n);
  first_ = bounds[static_cast<std::size_t>(world_rank())];
  count_ = bounds[static_cast<std::size_t>(world_rank()) + 1] - first_;
  if (count_ > std::numeric_limits<std::uint32_t>::max()) throw std::runtime_error("results.h5: a block over 2^32 rows");
  // The rows go to the ranks whose blocks hold them; runs ascend, so the destinations do too and the
  // packed rows are already grouped by destination (no send buffer). The global row of each is sent
  // once, here, so that the receiver knows where each row it gets goes in its block.
  send_rows_.assign(static_cast<std::size_t>(n), 0);
  std::vector<unsigned long long> index;
  int to = 0;
  for (const auto& run : runs)
    for (unsigned long long g = run[0]; g < run[0] + run[1]; ++g) {
      while (g >= bounds[static_cast<std::size_t>(to) + 1]) ++to;
      ++send_rows_[static_cast<std::size_t>(to)];
      index.push_back(g);
    }
  recv_rows_ = parallel::sparse_counts(send_rows_);
  send_at_ = offsets(send_rows_);
  recv_at_ = offsets(recv_rows_);
  std::vector<unsigned long long> got(static_cast<std::size_t>(recv_at_.back()));
  parallel::sparse_alltoallv(index.data(), send_rows_.data(), send_at_.data(), got.data(), recv_rows_.data(),
                             recv_at_.data(), MPI_UNSIGNED_LONG_LONG);
  if (got.size() != count_) throw std::runtime_error("results.h5: the ranks' rows do not cover the dataset once");
  place_.resize(got.size());
  for (std::size_t i = 0; i < got.size(); ++i) place_[i] = static_cast<std::uint32_t>(got[i] - first_);
}

std::vector<unsigned char> RowBlocks::gather(const void* data, std::size_t row_bytes) const {
  MPI_Datatype row = MPI_DATATYPE_NULL;  // one row as a unit, so that the counts stay in rows
  MPI_Type_contiguous(static_cast<int>(row_bytes), MPI_BYTE, &row);
  MPI_Type_commit(&row);
  std::vector<unsigned char> received(place_.size() * row_bytes), block(place_.size() * row_bytes);
  parallel::sparse_alltoallv(data, send_rows_.data(), send_at_.data(), received.data(), recv_rows_.data(),
                             recv_at_.data(), row);
  MPI_Type_free(&row);
  for (std::size_t i = 0; i < place_.size(); ++i)
    std::memcpy(block.data() + place_[i] * row_bytes, received.data() + i * row_bytes, row_bytes);
  return block;
}

}  // namespace tribex::solver::output
