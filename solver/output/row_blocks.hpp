// SPDX-License-Identifier: MIT
// A parallel results.h5 write of a rank's scattered rows through blocks of consecutive rows (issue 57,
// memory with results output on; solver/output/README.md "Parallel runs").
//
// A rank's rows of a global dataset (its owned nodes, its elements) are runs scattered over the global
// order. Written in place, parallel HDF5 1.10.8 maps that union of runs to the chunks element by element
// (span elements of the selection, about 40 MB per rank for a 250,000-element stress field) and nearly
// every chunk holds rows of every rank, so the filtered (gzip) collective write sends each chunk's pieces
// to one owner that holds them and the whole chunk at once (heaptrack, 4-rank counts_indenter.i run:
// 57 + 12 MB in H5D__chunk_collective_write on one rank). Instead the rows are first exchanged, one
// sparse exchange (parallel/sparse_exchange.hpp: messages only to the ranks with rows), so that every rank holds one block of consecutive rows (the even split of the rows,
// aligned to whole chunks), which it writes as one hyperslab: the chunk map comes from the hyperslab's
// bounds and at most the chunks at a block's ends are shared. The datasets hold the same values with the
// same chunks and filters; only where the chunks lie in the file changes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tribex::solver::output {

/// Collective over MPI_COMM_WORLD (every rank builds it with its own runs, at set-up).
class RowBlocks {
 public:
  /// runs: this rank's rows {first, count}, ascending (the rows of `data` in write()); rows: the
  /// dataset's rows; align: rank blocks start at multiples of this many rows (the chunk height; 1: none).
  RowBlocks(const std::vector<std::array<unsigned long long, 2>>& runs, unsigned long long rows,
            unsigned long long align);

  /// Block boundaries of `ranks` ranks: rank r's block is [bounds[r], bounds[r + 1]).
  static std::vector<unsigned long long> split(unsigned long long rows, unsigned long long align, int ranks);

  unsigned long long first() const { return first_; }  // this rank's block: [first, first + count)
  unsigned long long count() const { return count_; }

  /// Collective: `data` holds this rank's rows (run order, row_bytes each); returns its block's rows in
  /// global order (count() x row_bytes bytes; row_bytes the same on every rank).
  std::vector<unsigned char> gather(const void* data, std::size_t row_bytes) const;

 private:
  unsigned long long first_ = 0, count_ = 0;
  std::vector<int> send_rows_, send_at_, recv_rows_, recv_at_;  // rows to / from each rank, and offsets
  std::vector<std::uint32_t> place_;  // the block row of each received row, in received order
};

}  // namespace tribex::solver::output
