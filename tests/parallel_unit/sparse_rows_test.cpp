// SPDX-License-Identifier: MIT
// Sparse rows of a nodal sum (solver/parallel/sparse_rows.hpp, ContactRegion::exchange_rows): packed
// and applied, they give the dense exchange's bits, signed zeros and NaN included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "solver/parallel/sparse_rows.hpp"

using namespace tribex::solver::parallel;

namespace {

constexpr int kWidth = 4;

// A peer's rows: its values [node][kWidth] and, per list position, its node and the receiver's node.
struct Peer {
  std::vector<double> values;
  std::vector<int> source, target;
};

// Rows of every kind: +0.0 (most, as beside a contact zone), -0.0 in one or all values, NaN, numbers.
std::vector<double> random_rows(std::mt19937& rng, int nodes) {
  std::vector<double> v(static_cast<std::size_t>(kWidth) * nodes, 0.0);
  std::uniform_int_distribution<int> kind(0, 9);
  std::normal_distribution<double> number(0.0, 1e-9);
  for (int n = 0; n < nodes; ++n) {
    const int k = kind(rng);
    for (int i = 0; i < kWidth; ++i) {
      double& x = v[static_cast<std::size_t>(kWidth) * n + i];
      if (k == 6) x = i == 2 ? -0.0 : 0.0;
      if (k == 7) x = -0.0;
      if (k == 8) x = i == 1 ? std::numeric_limits<double>::quiet_NaN() : number(rng);
      if (k == 9) x = number(rng);
    }
  }
  return v;
}

std::vector<Peer> random_peers(std::mt19937& rng, int nodes) {
  std::vector<Peer> peers(3);
  std::uniform_int_distribution<int> node(0, nodes - 1);
  for (auto& p : peers) {
    p.values = random_rows(rng, nodes);
    for (int j = 0; j < 40; ++j) {  // receiver's nodes repeat across peers, as a node shared by several
      p.source.push_back(node(rng));
      p.target.push_back(node(rng));
    }
  }
  return peers;
}

// The dense exchange: every listed row travels and is added (assigned) in list order.
void dense(const std::vector<Peer>& peers, std::vector<double>& values, bool add) {
  for (const auto& p : peers)
    for (std::size_t j = 0; j < p.source.size(); ++j)
      for (int i = 0; i < kWidth; ++i) {
        const double row = p.values[kWidth * static_cast<std::size_t>(p.source[j]) + i];
        double& v = values[kWidth * static_cast<std::size_t>(p.target[j]) + i];
        v = add ? v + row : row;
      }
}

void sparse(const std::vector<Peer>& peers, std::vector<double>& values, bool add, int* doubles_sent) {
  *doubles_sent = 0;
  for (const auto& p : peers) {
    const int count = static_cast<int>(p.source.size());
    std::vector<double> message(static_cast<std::size_t>(kWidth + 1) * count);
    const int length = pack_nonzero_rows(p.values.data(), kWidth, p.source.data(), count, message.data());
    *doubles_sent += length;
    apply_rows(message.data(), length, kWidth, p.target.data(), count, values.data(), add);
  }
}

}  // namespace

TEST(SparseRows, AddAndAssignGiveTheDenseExchangesBits) {
  std::mt19937 rng(20261126);
  const int nodes = 30;
  for (int trial = 0; trial < 200; ++trial) {
    const auto peers = random_peers(rng, nodes);
    const auto start = random_rows(rng, nodes);  // the receiver's own partial sums
    for (const bool add : {true, false}) {
      std::vector<double> expected = start, got = start;
      dense(peers, expected, add);
      int sent = 0;
      sparse(peers, got, add, &sent);
      ASSERT_EQ(std::memcmp(expected.data(), got.data(), sizeof(double) * expected.size()), 0)
          << "trial " << trial << (add ? " add" : " assign");
      ASSERT_LT(sent, 3 * 40 * (kWidth + 1)) << "rows of +0.0 must not travel";
    }
  }
}

TEST(SparseRows, OnlyRowsWithANonzeroBitTravel) {
  // Rows: +0.0, -0.0 in one value, 1.0, +0.0, NaN: three travel, as (position, values).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {0, 0, 0, 0, 0, -0.0, 0, 0, 1, 2, 3, 4, 0, 0, 0, 0, nan, 0, 0, 0};
  const std::vector<int> rows = {0, 1, 2, 3, 4};
  std::vector<double> message(25, -7.0);
  const int length = pack_nonzero_rows(values.data(), kWidth, rows.data(), 5, message.data());
  ASSERT_EQ(length, 15);
  EXPECT_EQ(message[0], 1.0);
  EXPECT_TRUE(std::signbit(message[2]));
  EXPECT_EQ(message[5], 2.0);
  EXPECT_EQ(message[6], 1.0);
  EXPECT_EQ(message[10], 4.0);
  EXPECT_TRUE(std::isnan(message[11]));
  // Where the receiver holds -0.0, a row left out (+0.0) turns it into +0.0, as the dense sum does;
  // one sent as -0.0 keeps it.
  std::vector<double> held(20, -0.0);
  apply_rows(message.data(), length, kWidth, rows.data(), 5, held.data(), true);
  EXPECT_FALSE(std::signbit(held[0]));  // row 0 left out: -0.0 + 0.0 = +0.0
  EXPECT_TRUE(std::signbit(held[5]));   // row 1's -0.0: -0.0 + -0.0 = -0.0
  EXPECT_FALSE(std::signbit(held[4]));  // row 1's +0.0 values
  EXPECT_EQ(held[9], 2.0);
}
