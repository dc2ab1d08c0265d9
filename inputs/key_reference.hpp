// SPDX-License-Identifier: MIT
// The deck key reference, made from the schema (inputs/schema.cpp) and nothing else: every block with
// its NAME rule, where it may appear, its children and each key's value type, unit dimension, default
// and description. `tribex keys [BLOCK]` prints it; docs/deck_reference.md is the same text
// (`tribex keys --markdown`), kept equal to the schema by a CTest.
#pragma once

#include <string>

#include "inputs/schema.hpp"

namespace tribex::inputs {

/// The reference of one block, or of every block (nullptr), as Markdown (headings and a table per
/// block) or plain text for the terminal.
std::string key_reference(const BlockSchema* block, bool markdown);

}  // namespace tribex::inputs
