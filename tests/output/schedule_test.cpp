// SPDX-License-Identifier: MIT
// Schedule (solver/output/schedule.hpp): every call of done() is bounded (issue 54, item 9), and the
// usual case keeps the output times of the uninterrupted sum.
#include <gtest/gtest.h>

#include <chrono>

#include "solver/output/schedule.hpp"

namespace tribex::solver {
namespace {

TEST(Schedule, OneIntervalAtATimeIsTheRunningSum) {
  Schedule s(1e-12, std::nullopt, 0.0);
  double sum = 0.0;
  for (int k = 1; k <= 1000; ++k) {
    sum += 1e-12;
    s.done(sum - 1e-12);
    EXPECT_EQ(s.next(), sum) << "output " << k;  // bit for bit: the same additions as before the bound
  }
}

TEST(Schedule, FarBehindOrBelowResolutionEndsAtOnce) {
  const auto t0 = std::chrono::steady_clock::now();
  Schedule behind(1e-12, std::nullopt, -1.0);  // a restart file's results_next = -1
  behind.done(5e-12);
  EXPECT_GT(behind.next(), 5e-12);
  EXPECT_LE(behind.next(), 5e-12 + 1.0001e-12);
  Schedule huge(1e-12, std::nullopt, 0.0);  // time = 1e300
  huge.done(1e300);
  EXPECT_GT(huge.next(), 1e300);
  Schedule tiny(1e-30, std::nullopt, 0.0);  // an increment below the resolution of t
  tiny.done(1e-11);
  EXPECT_GT(tiny.next(), 1e-11);
  Schedule nan(1e-12, std::nullopt, std::nan(""));
  nan.done(1e-11);
  EXPECT_GT(nan.next(), 1e-11);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 0.5);
}

}  // namespace
}  // namespace tribex::solver
