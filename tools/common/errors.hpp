// SPDX-License-Identifier: MIT
// Exit codes of every tribex command (docs/architecture.md, "Interfaces users see") and the errors the
// command-line layer maps onto them. Layers below tools/ throw their own error types
// (inputs::DeckError, mesh::MeshError, solver::SetupError, solver::NumericalFailure); the front
// end in tools/cli/main.cpp maps each to one of these codes.
#pragma once

#include <stdexcept>
#include <string>

namespace tribex::tools {

enum ExitCode : int {
  exit_ok = 0,
  exit_internal_error = 1,
  exit_bad_input = 2,        // deck, mesh, data file or command-line arguments
  exit_numerical_failure = 3,
  exit_interrupted = 130,
};

/// Bad command-line arguments or a bad data file read by a tool: exit code 2.
/// The message is one line and names the argument or `file:line` and the fix.
class BadInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tribex::tools
