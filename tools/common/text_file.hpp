// SPDX-License-Identifier: MIT
// Writing a tool's output file so that a failed run leaves nothing half-written: the text goes to PATH.tmp,
// which is renamed onto PATH only once it is complete. Errors are tools::BadInput naming the path and the fix.
#pragma once

#include <string>

namespace tribex::tools {

/// Writes `text` to `path` through PATH.tmp and a rename. Only a regular file is replaced: a FIFO,
/// device, folder or symbolic link at PATH or PATH.tmp is BadInput (require_output_file).
void write_text_file(const std::string& path, const std::string& text);

/// BadInput (exit 2, one line) when `path` exists and is not a regular file (mesh/output_target.hpp):
/// every writer of the tools checks its output paths with it before it writes anything.
void require_output_file(const std::string& path);

/// As write_text_file, but an empty path or "-" prints `text` on stdout instead.
void write_text_output(const std::string& path, const std::string& text);

}  // namespace tribex::tools
