// SPDX-License-Identifier: MIT
// A restart file is read in a child process (issue 54): the HDF5 library walks a file's structures
// with its own code, and a crafted or damaged file can make it read or write outside its buffers
// (the restart fuzz target found a heap-buffer-overflow inside libhdf5 1.10.8). The child does the
// whole read, sends the archive's named arrays back through a pipe and exits; whatever the library
// does to the child's memory, the run's process only receives plain arrays, and a child that dies
// (signal, sanitizer abort) becomes a SetupError naming the file (exit 2).
#pragma once

#include <functional>
#include <string>

#include "solver/restart/state_archive.hpp"

namespace tribex::solver {

/// Runs `read` (a read of restart file `path`, e.g. read_restart_file) in a forked child and returns
/// the archive it produced. A SetupError in the child is rethrown here with its message; a child that
/// crashes or exits without an archive throws SetupError naming `path` and the signal or status.
StateArchive read_isolated(const std::string& path, const std::function<StateArchive()>& read);

}  // namespace tribex::solver
