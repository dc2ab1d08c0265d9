// SPDX-License-Identifier: MIT
// The subcommands of `tribex`; each takes the arguments after its name and returns an exit code.
// Errors are thrown, not returned: run_mapping_errors() turns them into exit codes.
#pragma once

#include <string>
#include <vector>

namespace tribex::cli {

int pstd_command(const std::vector<std::string>& args);  // tools/pstd/

}  // namespace tribex::cli
