// SPDX-License-Identifier: MIT
#pragma once

#include <stdexcept>

namespace tribex::mesh {

/// A mesh, mesh file or height-map file that cannot be used: exit code 2 at the command line.
/// The message is one line naming the file and the line or byte offset, what was expected, and
/// the fix where there is one.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tribex::mesh
