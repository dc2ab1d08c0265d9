// SPDX-License-Identifier: MIT
// Tree + schema -> typed Deck: reads each block's values (defaults from the schema), checks the
// rules that span keys or blocks (E/nu or K/G, exactly one output increment, t strictly
// increasing, termination > start) and every cross-reference (materials, models, sections,
// functions, finite element models), and writes the resolved text.
#pragma once

#include <string>

#include "inputs/deck.hpp"
#include "inputs/deck_tree.hpp"
#include "inputs/diagnostic_sink.hpp"

namespace tribex::inputs {

/// Builds the Deck from a tree that build_deck_tree made; problems go to `sink`.
Deck build_deck(const Scope& root, const std::string& file_name, DiagnosticSink& sink);

/// The deck re-emitted in deck syntax: every key of every block with its value or default, all
/// numbers in SI (shortest exact form), function tables scaled to SI. Parsing it again gives
/// the same Deck.
std::string resolved_text(const Scope& root);

}  // namespace tribex::inputs
