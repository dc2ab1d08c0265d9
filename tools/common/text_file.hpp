// SPDX-License-Identifier: MIT
// Writing a tool's output file so that a failed run leaves nothing half-written: the text goes to PATH.tmp,
// which is renamed onto PATH only once it is complete. Errors are tools::BadInput naming the path and the fix.
#pragma once

#include <string>

namespace tribex::tools {

/// Writes `text` to `path` through PATH.tmp and a rename.
void write_text_file(const std::string& path, const std::string& text);

/// As write_text_file, but an empty path or "-" prints `text` on stdout instead.
void write_text_output(const std::string& path, const std::string& text);

}  // namespace tribex::tools
