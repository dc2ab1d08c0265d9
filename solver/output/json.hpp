// SPDX-License-Identifier: MIT
// The two pieces every JSON output needs (RFC 8259): a quoted, escaped string and a number. Used by
// summary.json and, through tools/common/json.hpp, by the tools (tools depend on solver, not the
// reverse, so the one implementation lives here). Objects are composed from these; there is no DOM.
#pragma once

#include <string>

namespace tribex::solver {

/// `s` as a JSON string literal, quotes included: `"` and `\` escaped, control characters as \u00XX.
std::string json_string(const std::string& s);

/// `v` with `significant_digits` (%.*g; 9 for reports, 17 to round-trip a double); `null` for NaN
/// and infinities, which JSON cannot represent.
std::string json_number(double v, int significant_digits = 9);

}  // namespace tribex::solver
