// SPDX-License-Identifier: MIT
// The output folder of a run: what tribex writes there, and clearing an earlier run's files.
#pragma once

#include <cstddef>
#include <filesystem>

namespace tribex::solver {

/// A fresh run into an existing output folder first removes the files tribex writes there (an
/// earlier run's outputs and restart files, never anything else), so that runs are not mixed; a
/// symbolic link in one of those names is removed as a link, its target untouched. A resumed run
/// continues the folder (the caller does not clear it). Returns the count removed; throws
/// SetupError naming a file it cannot remove.
std::size_t clear_owned_outputs(const std::filesystem::path& folder);

}  // namespace tribex::solver
