// SPDX-License-Identifier: MIT
// The generic tree of a deck: scopes (`begin TYPE [NAME] ... end`) holding key lines and child
// scopes, every node with its location. Building it applies the schema's structural rules:
// which TYPEs may stand where (longest known TYPE prefix, the rest is the NAME), `end` matching,
// known keys (longest known key as a word prefix when no `=`/`is`/`are` is written), duplicate
// keys, required keys, NAME rules, child counts and every key's value (values.hpp).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "inputs/diagnostic_sink.hpp"
#include "inputs/lexer.hpp"
#include "inputs/schema.hpp"
#include "inputs/values.hpp"

namespace tribex::inputs {

struct KeyLine {
  const KeySchema* schema = nullptr;
  std::vector<Word> words;     // the value words
  std::optional<Value> value;  // nullopt when the value was bad (already reported)
  SourceLocation where;
};

struct Row {
  std::vector<double> numbers;
  SourceLocation where;
};

struct Scope {
  const BlockSchema* schema = nullptr;
  std::string name;        // as written (case kept); canonical when the schema lists names
  SourceLocation where;    // the `begin` line
  std::string path;        // "sierra/presto procedure/presto region"
  std::vector<KeyLine> keys;
  std::vector<Scope> children;
  std::vector<Row> rows;  // `begin values` tables
  std::vector<const KeySchema*> misspelt;  // keys a did-you-mean hint pointed to
  /// Root only: (TYPE, NAME) of blocks rejected as misplaced or misspelt (with a hint), so that
  /// references to them are not reported a second time as undefined.
  std::vector<std::pair<std::string, std::string>> rejected_blocks;

  const std::string& type() const { return schema->type; }
  const KeyLine* find(const std::string& key) const;
  std::vector<const Scope*> children_of(const std::string& type) const;
};

/// Builds the tree of the whole deck; the root's only child should be `sierra`.
Scope build_deck_tree(const std::vector<LogicalLine>& lines, const std::string& file_name, DiagnosticSink& sink);

}  // namespace tribex::inputs
