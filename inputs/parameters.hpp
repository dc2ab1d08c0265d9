// SPDX-License-Identifier: MIT
// Deck parameters (APREPRO style, inputs/README.md "Parameters"): a line of its own
// `{NAME = EXPRESSION}` defines NAME (once); `{EXPRESSION}` anywhere in a later line is replaced by
// its value: a dimensionless value by its shortest exact number, a value with a unit by its SI
// number glued to its SI unit ("5e-08m", "0.05J/m^2"), which the value parser reads as a number
// with a unit and checks against the key's dimension. `--set NAME=EXPRESSION` on the command line
// replaces the value of the deck's definition of NAME (a plain number there is SI of the
// definition's dimension, as plain numbers in the deck are SI of their key).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "inputs/lexer.hpp"
#include "inputs/units.hpp"

namespace tribex::inputs {

/// Parses "NAME=EXPRESSION" (the text after --set); nullopt and *error when it is not one.
std::optional<ParameterSetting> parse_parameter_setting(const std::string& text, std::string* error);

/// Replaces every `{...}` of `lines` by its value and drops the definition lines; fills
/// `parameters` in definition order. Problems go to `sink` (at the line and word at fault; a
/// --set naming no definition at `deck_file`:0:0, listing the names the deck defines).
std::vector<LogicalLine> expand_parameters(const std::vector<LogicalLine>& lines,
                                           const std::vector<ParameterSetting>& settings,
                                           const std::string& deck_file, std::vector<DeckParameter>& parameters,
                                           DiagnosticSink& sink);

/// The definition lines of the resolved deck ("{W = 0.06 J/m^2}", SI, one a line, definition order):
/// read again they define the same values (the resolved text round-trips).
std::string parameter_definitions_text(const std::vector<DeckParameter>& parameters);

}  // namespace tribex::inputs
