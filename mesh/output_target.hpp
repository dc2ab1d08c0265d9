// SPDX-License-Identifier: MIT
// The one check every writer of tribex makes before it replaces a path (mesh files, tool outputs,
// results): only a regular file is ever replaced. A FIFO, device, folder, socket or symbolic link
// under the name is refused (writing through a temporary file and a rename would replace it by a
// regular file; opening it would block on a FIFO or write into a device).
#pragma once

#include <string>

namespace tribex::mesh {

/// "" when `path` is absent or a regular file (links not followed); else why it may not be written,
/// e.g. "out.msh is a FIFO (named pipe), not a regular file".
std::string output_target_problem(const std::string& path);

/// MeshError (exit 2) with output_target_problem's reason and the fix, when there is one.
void require_output_target(const std::string& path);

/// The fix appended to a refusal: "; tribex replaces only regular files: give the path of a new or regular file".
extern const char* const output_target_fix;

}  // namespace tribex::mesh
