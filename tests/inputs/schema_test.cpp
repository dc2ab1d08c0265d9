// SPDX-License-Identifier: MIT
// Consistency of the schema table (inputs/schema.cpp).
#include <gtest/gtest.h>

#include <set>

#include "inputs/lexer.hpp"
#include "inputs/schema.hpp"
#include "inputs/values.hpp"

using namespace tribex::inputs;

TEST(Schema, EveryDefaultParsesAndIsInRange) {
  for (const auto& b : all_block_schemas()) {
    for (const auto& k : b.keys) {
      if (k.default_text.empty()) continue;
      EXPECT_NO_THROW({
        auto v = default_value(k);
        EXPECT_TRUE(v.has_value()) << b.type << "/" << k.name;
      }) << b.type << "/" << k.name;
      EXPECT_FALSE(k.required) << b.type << "/" << k.name << ": a required key has no use for a default";
    }
  }
}

TEST(Schema, NamesAreLowerCaseUniqueAndChildrenExist) {
  std::set<std::string> types;
  for (const auto& b : all_block_schemas()) {
    EXPECT_EQ(lower(b.type), b.type);
    EXPECT_TRUE(types.insert(b.type).second) << "duplicate block type " << b.type;
    std::set<std::string> keys;
    for (const auto& k : b.keys) {
      EXPECT_EQ(lower(k.name), k.name);
      EXPECT_TRUE(keys.insert(k.name).second) << b.type << ": duplicate key " << k.name;
    }
    for (const auto& c : b.children) EXPECT_NE(find_block_schema(c.type), nullptr) << b.type << " -> " << c.type;
  }
  ASSERT_EQ(root_schema().children.size(), 1u);
  EXPECT_EQ(root_schema().children[0].type, "sierra");
}

TEST(Schema, RangesPrintForMessages) {
  EXPECT_EQ((Range{-1.0, 0.5, true, true}).str(), "in (-1, 0.5)");
  EXPECT_EQ((Range{0.0, 1.0, true, false}).str(), "in (0, 1]");
  Range positive;
  positive.lo = 0.0;
  positive.lo_open = true;
  EXPECT_EQ(positive.str(), "> 0");
  EXPECT_TRUE(positive.contains(1e-300));
  EXPECT_FALSE(positive.contains(0.0));
}

TEST(Schema, ChoicesAndAliases) {
  EXPECT_EQ(canonical_choice("NeoHookean", {"elastic", "neo_hookean"}, {{"neohookean", "neo_hookean"}}), "neo_hookean");
  EXPECT_EQ(canonical_choice("plastic", {"elastic", "neo_hookean"}, {}), "");
  EXPECT_EQ(join_choices({"x", "y", "z"}), "x, y or z");
}
