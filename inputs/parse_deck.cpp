// SPDX-License-Identifier: MIT
// The entry points: lexer -> tree (with schema and value checks) -> Deck; all diagnostics of all
// stages are collected and thrown together.
#include "inputs/check_deck.hpp"
#include "inputs/deck_builder.hpp"
#include "inputs/diagnostics.hpp"
#include "inputs/parameters.hpp"

namespace tribex::inputs {
namespace {

Deck parse_lines(const std::vector<LogicalLine>& raw_lines, const std::string& file_name,
                 const std::vector<ParameterSetting>& settings, DiagnosticSink& sink) {
  std::vector<DeckParameter> parameters;
  const std::vector<LogicalLine> lines = expand_parameters(raw_lines, settings, file_name, parameters, sink);
  sink.throw_if_any();  // a bad parameter would only repeat itself in the keys that use it
  const Scope root = build_deck_tree(lines, file_name, sink);
  Deck deck = build_deck(root, file_name, sink);
  sink.throw_if_any();
  deck.resolved_text = resolved_text(root);  // its first line is a comment; the definitions go below it
  deck.resolved_text.insert(deck.resolved_text.find('\n') + 1, parameter_definitions_text(parameters));
  deck.parameters = std::move(parameters);
  for (const auto& line : lines)  // the deck and its includes (an output folder must not overwrite them)
    if (deck.files_read.empty() || deck.files_read.back() != line.where().file) deck.files_read.push_back(line.where().file);
  return deck;
}

}  // namespace

Deck parse_deck_file(const std::string& path, const std::vector<ParameterSetting>& settings) {
  DiagnosticSink sink;
  const auto lines = lex_deck_file(path, sink);
  return parse_lines(lines, path, settings, sink);
}

Deck parse_deck_string(const std::string& text, const std::string& file_name,
                       const std::vector<ParameterSetting>& settings) {
  DiagnosticSink sink;
  const auto lines = lex_deck_text(text, file_name, sink);
  return parse_lines(lines, file_name, settings, sink);
}

std::vector<Diagnostic> check_deck_file(const std::string& path, const std::vector<ParameterSetting>& settings) {
  try {
    parse_deck_file(path, settings);
  } catch (const DeckError& e) {
    return e.diagnostics();
  }
  return {};
}

}  // namespace tribex::inputs
