// SPDX-License-Identifier: MIT
// The deck key reference (inputs/key_reference, `tribex keys`) covers every schema entry: each block
// has its heading, each key its row with the value type, default and description the schema gives;
// the material models and contact laws come from their lists (no list of names is written here).
#include <gtest/gtest.h>

#include <string>

#include "inputs/declared_keys.hpp"
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
  // The choices are the list's (contact/laws/contact_law.hpp), in its order: "a, b, ... or z".
  const std::vector<std::string> laws = contact::law_names();
  std::string choices;
  for (std::size_t i = 0; i < laws.size(); ++i)
    choices += (i == 0 ? "" : i + 1 == laws.size() ? " or " : ", ") + laws[i];
  EXPECT_NE(text.find("  model = one of: " + choices + ", default frictionless"), std::string::npos) << text;
}

// Every law's and every material model's declared keys have their line, naming the model.
TEST(KeyReference, ListsTheKeysOfEveryLawAndMaterialModel) {
  auto expect_keys = [](const char* block, const ModelList& list) {
    const BlockSchema* b = find_block_schema(block);
    ASSERT_NE(b, nullptr) << block;
    const std::string text = key_reference(b, true);
    for (std::size_t m = 0; m < list.names.size(); ++m)
      for (const keys::KeyDecl& k : list.keys[m]) {
        const auto row = text.find("| `" + std::string(k.key) + "` |");
        ASSERT_NE(row, std::string::npos) << block << ": " << k.key;
        const std::string line = text.substr(row, text.find('\n', row) - row);
        EXPECT_NE(line.find(list.names[m]), std::string::npos) << line;
      }
  };
  expect_keys("interaction", contact_law_list());
  expect_keys("parameters for model", material_model_list());
  const BlockSchema* models = find_block_schema("parameters for model");
  ASSERT_NE(models, nullptr);
  EXPECT_EQ(models->name_allowed, materials::model_names());
}

}  // namespace
}  // namespace tribex::inputs
