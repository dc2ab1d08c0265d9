// SPDX-License-Identifier: MIT
// Unit-aware numbers (inputs/units.hpp): SI conversion factors are exact decimal definitions, so
// the tolerance is a few ulp (relative 1e-15).
#include <gtest/gtest.h>

#include "inputs/units.hpp"
#include "inputs/values.hpp"

using namespace tribex::inputs;

namespace {

Quantity q(const char* text) {
  std::string error;
  auto v = parse_quantity(text, &error);
  EXPECT_TRUE(v.has_value()) << text << ": " << error;
  return v.value_or(Quantity{});
}

TEST(Units, LengthsWithAndWithoutBlank) {
  EXPECT_NEAR(q("27 nm").value, 2.7e-8, 1e-15 * 2.7e-8);
  EXPECT_NEAR(q("27nm").value, 2.7e-8, 1e-15 * 2.7e-8);
  EXPECT_EQ(q("27 nm").dimension, dim::length);
  EXPECT_NEAR(q("3 A").value, 3e-10, 1e-25);  // angstrom
}

TEST(Units, TheDeckExamples) {
  EXPECT_NEAR(q("161 GPa").value, 161e9, 1e-15 * 161e9);
  EXPECT_EQ(q("161 GPa").dimension, dim::pressure);
  EXPECT_NEAR(q("0.05 J/m^2").value, 0.05, 1e-17);
  EXPECT_EQ(q("0.05 J/m^2").dimension, dim::energy_per_area);
  EXPECT_NEAR(q("2330 kg/m^3").value, 2330.0, 1e-12);
  EXPECT_EQ(q("2330 kg/m^3").dimension, dim::density);
  EXPECT_NEAR(q("10 ps").value, 1e-11, 1e-26);
  EXPECT_EQ(q("10 ps").dimension, dim::time);
  EXPECT_NEAR(q("1e8 1/s").value, 1e8, 1e-7);
  EXPECT_EQ(q("1e8 1/s").dimension, dim::rate);
  EXPECT_EQ(q("-1 m/s").dimension, dim::velocity);
  EXPECT_EQ(q("1.5").dimension, dim::none);
}

TEST(Units, Rejections) {
  std::string error;
  EXPECT_FALSE(parse_quantity("27 furlongs", &error));
  EXPECT_NE(error.find("unknown unit 'furlongs'"), std::string::npos);
  EXPECT_FALSE(parse_quantity("nan", &error));
  EXPECT_FALSE(parse_quantity("1e400", &error));
  EXPECT_FALSE(parse_quantity("1 m/s/s", &error));
  EXPECT_FALSE(parse_quantity("", &error));
}

TEST(Units, DimensionNamesForMessages) {
  EXPECT_EQ(describe_dimension(dim::pressure), "a pressure (Pa)");
  EXPECT_EQ(describe_dimension(dim::length), "a length (m)");
  EXPECT_EQ(describe_dimension(dim::none), "a dimensionless number");
}

}  // namespace
