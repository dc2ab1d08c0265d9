// SPDX-License-Identifier: MIT
// The parallel results.h5 write's exchange into blocks of whole chunks (solver/output/row_blocks.hpp),
// run under mpiexec at 1, 2 and 4 ranks (tests/parallel_unit/CMakeLists.txt): the split's bounds, and
// that every rank's block, gathered from rows scattered over the ranks (every row on one rank), is
// exactly the global rows [first, first + count) in global order, bytes as given, for rows of doubles
// and of ints, with rows dealt round-robin, in runs, or all on rank 0 (the whole-mesh form).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstring>
#include <vector>

#include "solver/output/row_blocks.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex {
namespace {

using solver::output::RowBlocks;
using Runs = std::vector<std::array<unsigned long long, 2>>;

TEST(RowBlocks, SplitGivesWholeChunksAsEvenAsTheyGo) {
  // 10 rows in chunks of 3 (the last one short): 4 chunks over 4 ranks, one each.
  EXPECT_EQ(RowBlocks::split(10, 3, 4), (std::vector<unsigned long long>{0, 3, 6, 9, 10}));
  // 2 chunks of 4 over 4 ranks: ranks 0 and 2 get none.
  EXPECT_EQ(RowBlocks::split(5, 4, 4), (std::vector<unsigned long long>{0, 0, 4, 4, 5}));
  // 7 chunks of 2 over 3 ranks: chunks 0-1, 2-3, 4-6.
  EXPECT_EQ(RowBlocks::split(14, 2, 3), (std::vector<unsigned long long>{0, 4, 8, 14}));
  EXPECT_EQ(RowBlocks::split(0, 5, 2), (std::vector<unsigned long long>{0, 0, 0}));
  EXPECT_EQ(RowBlocks::split(7, 1, 1), (std::vector<unsigned long long>{0, 7}));
}

// Row g's values: 3 doubles g + 0.25 c (c the column), or 8 ints 8 g + c.
std::vector<double> double_rows(const Runs& runs) {
  std::vector<double> v;
  for (const auto& r : runs)
    for (unsigned long long g = r[0]; g < r[0] + r[1]; ++g)
      for (int c = 0; c < 3; ++c) v.push_back(static_cast<double>(g) + 0.25 * c);
  return v;
}

std::vector<int> int_rows(const Runs& runs) {
  std::vector<int> v;
  for (const auto& r : runs)
    for (unsigned long long g = r[0]; g < r[0] + r[1]; ++g)
      for (int c = 0; c < 8; ++c) v.push_back(static_cast<int>(8 * g) + c);
  return v;
}

void expect_blocks(const Runs& mine, unsigned long long rows, unsigned long long align) {
  const int n = solver::parallel::size(), me = solver::parallel::rank();
  const RowBlocks blocks(mine, rows, align);
  const auto bounds = RowBlocks::split(rows, align, n);
  ASSERT_EQ(blocks.first(), bounds[me]);
  ASSERT_EQ(blocks.count(), bounds[me + 1] - bounds[me]);
  const Runs block_run{{blocks.first(), blocks.count()}};
  const std::vector<double> d = double_rows(mine), want_d = double_rows(block_run);
  const std::vector<unsigned char> got_d = blocks.gather(d.data(), 3 * sizeof(double));
  ASSERT_EQ(got_d.size(), want_d.size() * sizeof(double));
  EXPECT_EQ(std::memcmp(got_d.data(), want_d.data(), got_d.size()), 0) << "rank " << me;
  const std::vector<int> i = int_rows(mine), want_i = int_rows(block_run);
  const std::vector<unsigned char> got_i = blocks.gather(i.data(), 8 * sizeof(int));
  ASSERT_EQ(got_i.size(), want_i.size() * sizeof(int));
  EXPECT_EQ(std::memcmp(got_i.data(), want_i.data(), got_i.size()), 0) << "rank " << me;
}

TEST(RowBlocks, GathersRowsDealtRoundRobin) {
  const int n = solver::parallel::size(), me = solver::parallel::rank();
  const unsigned long long rows = 23;
  Runs mine;
  for (unsigned long long g = static_cast<unsigned long long>(me); g < rows; g += static_cast<unsigned long long>(n))
    mine.push_back({g, 1});
  expect_blocks(mine, rows, 4);
  expect_blocks(mine, rows, 1);
}

TEST(RowBlocks, GathersRunsOfRows) {
  // Runs of 5 rows dealt to the ranks in reverse order (rank n-1 first), 41 rows, chunks of 6.
  const int n = solver::parallel::size(), me = solver::parallel::rank();
  const unsigned long long rows = 41;
  Runs mine;
  for (unsigned long long at = 0, k = 0; at < rows; at += 5, ++k)
    if (static_cast<int>(n - 1 - static_cast<int>(k % static_cast<unsigned long long>(n))) == me)
      mine.push_back({at, std::min<unsigned long long>(5, rows - at)});
  expect_blocks(mine, rows, 6);
}

TEST(RowBlocks, GathersEveryRowFromRankZero) {
  // The whole-mesh form: rank 0 writes all the rows, the others none.
  const unsigned long long rows = 30;
  expect_blocks(solver::parallel::is_root() ? Runs{{0, rows}} : Runs{}, rows, 7);
}

}  // namespace
}  // namespace tribex
