// SPDX-License-Identifier: MIT
// The two pieces every tool's JSON output needs (RFC 8259): a quoted, escaped string and a number that
// round-trips to 9 significant digits. Tools compose their objects from these; there is no DOM here.
#pragma once

#include <string>

namespace tribex::tools {

/// `s` as a JSON string literal, quotes included: `"` and `\` escaped, control characters as \u00XX.
std::string json_string(const std::string& s);

/// `v` with 9 significant digits (%.9g); `null` for NaN and infinities, which JSON cannot represent.
std::string json_number(double v);

}  // namespace tribex::tools
