// SPDX-License-Identifier: MIT
// `tribex keys [BLOCK] [--markdown]`: the deck key reference from the schema (inputs/key_reference.hpp).
#include <cstdio>
#include <string>
#include <vector>

#include "inputs/did_you_mean.hpp"
#include "inputs/key_reference.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"

namespace tribex::cli {

int keys_command(const std::vector<std::string>& argv) {
  const char* usage =
      "usage: tribex keys [BLOCK] [--markdown]\n"
      "Every deck block and key from the schema: NAME rule, where the block goes, the blocks inside it, and\n"
      "each key's value type, unit dimension, default and description. BLOCK (words, e.g. 'interaction' or\n"
      "'generated asperity') prints that block only; --markdown prints the text of docs/deck_reference.md.\n";
  tools::Args a(argv, "tribex keys", usage, {"--markdown"});
  if (a.answered_help()) return tools::exit_ok;
  const bool markdown = a.flag("--markdown");
  std::string block;
  for (std::size_t i = 0; i < a.positional_count(); ++i) {
    if (!block.empty()) block += ' ';
    block += a.positional(i, "BLOCK");
  }
  a.finish();
  const inputs::BlockSchema* schema = nullptr;
  if (!block.empty()) {
    schema = inputs::find_block_schema(block);
    if (!schema) {
      std::vector<std::string> types;
      for (const auto& b : inputs::all_block_schemas())
        if (!b.type.empty()) types.push_back(b.type);
      const std::string hint = inputs::closest_match(block, types);
      throw tools::BadInput("no deck block '" + block + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?") +
                            " (tribex keys lists them all)");
    }
  }
  std::fputs(inputs::key_reference(schema, markdown).c_str(), stdout);
  return tools::exit_ok;
}

}  // namespace tribex::cli
