// SPDX-License-Identifier: MIT
// The sparse exchange (solver/parallel/sparse_exchange.hpp), run under mpiexec at 1, 2 and 4 ranks
// (tests/parallel_unit/CMakeLists.txt): on patterns with zero counts (a ring, one rank receiving from all,
// a rank sending nothing, everything to itself), many calls in a row and a sub-communicator, the counts are
// MPI_Alltoall's and the values MPI_Alltoallv's, bit for bit, and a rank exchanges with exactly the ranks it
// has data for (sparse_exchange_peers).
#include <gtest/gtest.h>
#include <mpi.h>

#include <functional>
#include <vector>

#include "solver/parallel/sparse_exchange.hpp"

namespace tribex {
namespace {

using solver::parallel::sparse_alltoallv;
using solver::parallel::sparse_counts;

// count[to] of rank `from`'s values for rank `to` under a pattern, and value k of them.
using Pattern = std::function<int(int from, int to, int ranks)>;
double value(int from, int to, int k) { return 1000.0 * from + to + 1e-3 * k + 1.0 / 3.0; }

// One exchange of the pattern on `comm`, checked against MPI_Alltoall + MPI_Alltoallv.
void check_pattern(const Pattern& pattern, MPI_Comm comm) {
  int ranks = 1, me = 0;
  MPI_Comm_size(comm, &ranks);
  MPI_Comm_rank(comm, &me);
  std::vector<int> count(ranks), at(ranks + 1, 0);
  std::vector<double> data;
  for (int r = 0; r < ranks; ++r) {
    count[r] = pattern(me, r, ranks);
    at[r + 1] = at[r] + count[r];
    for (int k = 0; k < count[r]; ++k) data.push_back(value(me, r, k));
  }
  const std::vector<int> received = sparse_counts(count, comm);
  std::vector<int> dense(ranks), recv_at(ranks + 1, 0);
  MPI_Alltoall(count.data(), 1, MPI_INT, dense.data(), 1, MPI_INT, comm);
  ASSERT_EQ(received, dense);
  for (int r = 0; r < ranks; ++r) recv_at[r + 1] = recv_at[r] + received[r];
  std::vector<double> sparse(recv_at[ranks] + 1, -1.0), want(recv_at[ranks] + 1, -1.0);
  sparse_alltoallv(data.data(), count.data(), at.data(), sparse.data(), received.data(), recv_at.data(), MPI_DOUBLE, comm);
  MPI_Alltoallv(data.data(), count.data(), at.data(), MPI_DOUBLE, want.data(), received.data(), recv_at.data(), MPI_DOUBLE,
                comm);
  EXPECT_EQ(sparse, want);
  for (int r = 0; r < ranks; ++r)
    for (int k = 0; k < received[r]; ++k) EXPECT_EQ(sparse[recv_at[r] + k], value(r, me, k));
}

const std::vector<Pattern>& patterns() {
  static const std::vector<Pattern> list = {
      [](int from, int to, int n) { return to == (from + 1) % n ? 3 : 0; },                 // a ring
      [](int, int to, int) { return to == 0 ? 2 : 0; },                                      // all to rank 0
      [](int from, int to, int) { return from == 0 ? 0 : (from + to) % 3; },                 // rank 0 sends nothing
      [](int from, int to, int) { return from == to ? 5 : 0; },                              // only to itself
      [](int, int, int) { return 0; },                                                       // nothing at all
      [](int from, int to, int) { return 1 + from * 7 + to; },                               // every pair
  };
  return list;
}

// First in the file (GoogleTest runs a file's tests in order; the tally is the process's): a ring makes a rank
// exchange with its two neighbours only (the one after it and the one before), whatever the rank count.
TEST(SparseExchange, ARankExchangesOnlyWithTheRanksItHasDataFor) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  check_pattern(patterns().front(), MPI_COMM_WORLD);
  EXPECT_EQ(solver::parallel::sparse_exchange_peers(), ranks == 1 ? 0 : ranks == 2 ? 1 : 2);
  check_pattern(patterns().back(), MPI_COMM_WORLD);  // every pair: every rank
  EXPECT_EQ(solver::parallel::sparse_exchange_peers(), ranks - 1);
}

TEST(SparseExchange, EqualsAlltoallvOnPatternsWithZeroCountsManyTimesInARow) {
  for (int round = 0; round < 20; ++round)  // back-to-back calls: no count or value of one taken for another's
    for (const auto& p : patterns()) check_pattern(p, MPI_COMM_WORLD);
}

TEST(SparseExchange, WorksOnASubCommunicator) {
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  MPI_Comm odd_even = MPI_COMM_NULL;
  MPI_Comm_split(MPI_COMM_WORLD, me % 2, me, &odd_even);
  for (const auto& p : patterns()) check_pattern(p, odd_even);
  MPI_Comm_free(&odd_even);
}

}  // namespace
}  // namespace tribex
