// SPDX-License-Identifier: MIT
// The deck key reference (inputs/key_reference, `tribex keys`) covers every schema entry: each block
// has its heading, each key its row with the value type, default and description the schema gives.
#include <gtest/gtest.h>

#include <string>

#include "inputs/key_reference.hpp"

namespace tribex::inputs {
namespace {

TEST(KeyReference, CoversEveryBlockAndKeyOfTheSchema) {
  const std::string text = key_reference(nullptr, true);
  int blocks = 0, keys = 0;
  for (const BlockSchema& b : all_block_schemas()) {
    if (b.type.empty()) continue;
    ++blocks;
    const std::string block = key_reference(&b, true);
    EXPECT_NE(text.find("## `begin " + b.type + "`\n\n" + b.help), std::string::npos) << b.type;
    EXPECT_NE(text.find(block), std::string::npos) << b.type;
    for (const KeySchema& k : b.keys) {
      ++keys;
      const auto row = block.find("| `" + k.name + "` |");
      ASSERT_NE(row, std::string::npos) << b.type << ": " << k.name;
      const std::string line = block.substr(row, block.find('\n', row) - row);
      if (!k.default_text.empty()) {
        std::string cell = "| ";
        cell += k.default_text;
        cell += " |";
        EXPECT_NE(line.find(cell), std::string::npos) << line;
      }
      for (const std::string& choice : k.allowed) EXPECT_NE(line.find(choice), std::string::npos) << line;
      if (!(k.dimension == dim::none)) {
        std::string unit = "[";  // (not "[" + str: GCC 12's -Wrestrict false positive)
        unit += k.dimension.str();
        unit += ']';
        EXPECT_NE(line.find(unit), std::string::npos) << line;
      }
      EXPECT_NE(line.find(k.required ? "| yes |" : "|  |"), std::string::npos) << line;
    }
  }
  EXPECT_GT(blocks, 20);  // the walk saw the schema (26 blocks, 125 keys on 2026-11-25)
  EXPECT_GT(keys, 100);
}

TEST(KeyReference, PlainTextOfOneBlock) {
  const BlockSchema* b = find_block_schema("interaction");
  ASSERT_NE(b, nullptr);
  const std::string text = key_reference(b, false);
  EXPECT_EQ(text.rfind("begin interaction    (NAME required; inside: contact definition)", 0), 0u) << text;
  EXPECT_NE(text.find("  static friction coefficient = number\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  model = one of: frictionless, adhesion, junction, rough surface or coulomb, default frictionless"),
            std::string::npos);
}

}  // namespace
}  // namespace tribex::inputs
