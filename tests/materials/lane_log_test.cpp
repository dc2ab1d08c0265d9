// SPDX-License-Identifier: MIT
// materials/lane_log.hpp: the kernels' logarithm against the correctly rounded one (long double
// log rounded to double), its special values, and a lane's result independent of its partner.
// (Widths 4 and 8 run the same template in the AVX2 / AVX-512 objects: tests/solver/element_lanes_test.cpp
// checks the neo-Hookean forces bitwise across widths.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "materials/lanes.hpp"

namespace {

using tribex::materials::double2;
using tribex::materials::lane_log;

/// |approx - log x| in units of the last place of the correctly rounded log x.
double ulp_error(double x, double approx) {
  const long double exact = std::log(static_cast<long double>(x));
  const double rounded = static_cast<double>(exact);
  const double ulp = std::nextafter(std::fabs(rounded), std::numeric_limits<double>::infinity()) - std::fabs(rounded);
  return static_cast<double>(std::fabs(static_cast<long double>(approx) - exact) / ulp);
}

TEST(LaneLog, BelowOneUlpOverTheWholeRangeAndNearOne) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> exponent(-740.0, 709.0), near_one(-1e-3, 1e-3), jacobian(0.3, 3.0);
  double worst = 0.0;
  for (int i = 0; i < 300000; ++i)
    for (const double x : {std::exp(exponent(rng)), 1.0 + near_one(rng), jacobian(rng), 1.0 + 1e-12 * near_one(rng)}) {
      if (x == 1.0) continue;
      worst = std::max(worst, ulp_error(x, lane_log(x)));
    }
  // fdlibm's bound for this algorithm is 1 ulp; libmvec's routine it replaced allowed 4
  EXPECT_LT(worst, 1.0);
  EXPECT_GT(worst, 0.5);  // not correctly rounded everywhere: the comparison above is a real one
}

TEST(LaneLog, ExactAndSpecialValues) {
  EXPECT_EQ(lane_log(1.0), 0.0);
  EXPECT_EQ(lane_log(2.0), static_cast<double>(std::log(2.0L)));
  EXPECT_EQ(lane_log(std::ldexp(1.0, -1074)), static_cast<double>(-1074 * std::log(2.0L)));  // smallest subnormal
  EXPECT_LT(ulp_error(3e-310, lane_log(3e-310)), 1.0);
  EXPECT_EQ(lane_log(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(lane_log(-0.0), -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(lane_log(-1e-300)));  // an inverted element: J < 0
  EXPECT_TRUE(std::isnan(lane_log(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(lane_log(-std::numeric_limits<double>::infinity())));
  EXPECT_EQ(lane_log(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
  EXPECT_EQ(lane_log(std::numeric_limits<double>::max()), static_cast<double>(std::log(static_cast<long double>(std::numeric_limits<double>::max()))));
}

TEST(LaneLog, ALaneDoesNotDependOnItsPartner) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> j(0.2, 5.0);
  for (int i = 0; i < 10000; ++i) {
    const double a = j(rng), b = j(rng);
    const double2 pair = lane_log(double2{a, b});
    EXPECT_EQ(pair[0], lane_log(a));
    EXPECT_EQ(pair[1], lane_log(b));
    const double2 special = lane_log(double2{a, -1.0});
    EXPECT_EQ(special[0], pair[0]);
    EXPECT_TRUE(std::isnan(special[1]));
  }
}

}  // namespace
