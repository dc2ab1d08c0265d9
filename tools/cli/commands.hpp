// SPDX-License-Identifier: MIT
// The subcommands of `tribex`; each takes the arguments after its name and returns an exit code.
// Errors are thrown, not returned: run_mapping_errors() turns them into exit codes.
#pragma once

#include <string>
#include <vector>

namespace tribex::cli {

/// tools/friction_test/command.cpp: `tribex friction-test calibrate|static|dynamic|synth`.
int friction_test_command(const std::vector<std::string>& args);

}  // namespace tribex::cli
