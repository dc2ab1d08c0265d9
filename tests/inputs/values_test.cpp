// SPDX-License-Identifier: MIT
// Typed key values (inputs/values.hpp) for the kinds the current schema does not exercise fully.
#include <gtest/gtest.h>

#include "inputs/values.hpp"

using namespace tribex::inputs;

namespace {

std::vector<Word> words(std::initializer_list<const char*> ws) {
  std::vector<Word> out;
  int col = 1;
  for (const char* w : ws) {
    out.push_back({w, {"v.i", 1, col}});
    col += 5;
  }
  return out;
}

std::optional<Value> convert(const KeySchema& k, std::initializer_list<const char*> ws, DiagnosticSink& sink) {
  return convert_value(k, words(ws), {"v.i", 1, 1}, "scope", sink);
}

TEST(Values, Booleans) {
  KeySchema k;
  k.name = "flag";
  k.kind = ValueKind::boolean;
  DiagnosticSink sink;
  EXPECT_TRUE(convert(k, {"ON"}, sink)->flag);
  EXPECT_TRUE(convert(k, {"yes"}, sink)->flag);
  EXPECT_FALSE(convert(k, {"false"}, sink)->flag);
  EXPECT_TRUE(sink.empty());
  EXPECT_FALSE(convert(k, {"maybe"}, sink).has_value());
  EXPECT_EQ(sink.size(), 1u);
}

TEST(Values, IntegersAndTheirRange) {
  KeySchema k;
  k.name = "n";
  k.kind = ValueKind::integers;
  k.count = 2;
  k.range.lo = 1;
  DiagnosticSink sink;
  EXPECT_EQ(convert(k, {"3", "+4"}, sink)->numbers, (std::vector<double>{3, 4}));
  EXPECT_FALSE(convert(k, {"3"}, sink));
  EXPECT_FALSE(convert(k, {"3", "0"}, sink));
  EXPECT_FALSE(convert(k, {"3", "99999999999"}, sink));
  EXPECT_EQ(sink.size(), 3u);
}

TEST(Values, EnumerationListsRejectRepeats) {
  KeySchema k;
  k.name = "components";
  k.kind = ValueKind::enumerations;
  k.allowed = {"x", "y", "z"};
  DiagnosticSink sink;
  EXPECT_EQ(convert(k, {"Z", "x"}, sink)->words, (std::vector<std::string>{"z", "x"}));
  EXPECT_FALSE(convert(k, {"x", "x"}, sink));
  EXPECT_EQ(sink.size(), 1u);
}

TEST(Values, SharedTrailingUnitAndGluedUnit) {
  KeySchema k;
  k.name = "size";
  k.kind = ValueKind::reals;
  k.count = 3;
  k.dimension = dim::length;
  DiagnosticSink sink;
  auto v = convert(k, {"100", "20", "50", "nm"}, sink);
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->numbers[2], 5e-8, 1e-23);
  v = convert(k, {"1nm", "2", "3um"}, sink);
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->numbers[0], 1e-9, 1e-24);
  EXPECT_EQ(v->numbers[1], 2.0);  // plain numbers are SI
  EXPECT_NEAR(v->numbers[2], 3e-6, 1e-21);
  EXPECT_TRUE(sink.empty());
  EXPECT_FALSE(convert(k, {"1nm", "2", "3", "nm"}, sink));  // unit given twice
  EXPECT_FALSE(convert(k, {"1", "2", "3", "GPa"}, sink));   // wrong dimension
  EXPECT_EQ(sink.size(), 2u);
}

TEST(Values, FormatRoundTrips) {
  KeySchema k;
  k.name = "t";
  k.kind = ValueKind::real;
  k.dimension = dim::time;
  DiagnosticSink sink;
  auto v = convert(k, {"0.1", "ps"}, sink);
  ASSERT_TRUE(v);
  const std::string text = format_value(k, *v);
  EXPECT_EQ(plain_number(text).value(), v->numbers[0]);
}

}  // namespace
