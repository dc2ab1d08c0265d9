// SPDX-License-Identifier: MIT
// Output writers refusing a folder they cannot create (tests/output): the paths that cannot be created and the
// one-line message of the SetupError a constructor throws there.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "solver/errors.hpp"

namespace tribex::test {

/// DIR/a_file/out with a_file a regular file: a folder no one can create (DIR is created first).
inline std::string path_under_a_file(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "a_file") << "not a directory\n";
  return (dir / "a_file" / "out").string();
}

/// The message of the solver::SetupError that `make()` throws; "no SetupError" when it throws none.
template <class Make>
std::string setup_error_of(Make make) {
  try {
    make();
  } catch (const solver::SetupError& e) {
    return e.what();
  }
  return "no SetupError";
}

}  // namespace tribex::test
