// SPDX-License-Identifier: MIT
// The deck checker (`tribex check` calls it): parse and validate only, nothing is run or written.
#pragma once

#include <string>
#include <vector>

#include "inputs/diagnostics.hpp"
#include "inputs/parameters.hpp"

namespace tribex::inputs {

/// Every problem of the deck file (empty when it is valid). Never throws DeckError.
std::vector<Diagnostic> check_deck_file(const std::string& path, const std::vector<ParameterSetting>& settings = {});

}  // namespace tribex::inputs
