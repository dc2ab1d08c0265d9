// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

namespace tribex::inputs {

/// Case-insensitive Levenshtein distance.
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The candidate closest to `word` if it is close enough to be a plausible misspelling
/// (distance <= max(2, |word|/3)), else "". Used for every did-you-mean hint in tribex.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace tribex::inputs
