// SPDX-License-Identifier: MIT
#pragma once

#include <stdexcept>
#include <string>

namespace tribex::solver {

/// The deck and the mesh disagree (a node set, side set or block named in the deck that the mesh
/// lacks, an empty set, ...): bad input, exit code 2. The message names the deck line.
class SetupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The run cannot go on (NaN, inverted element, time-step collapse, energy error over the limit):
/// exit code 3. The message names the element or node, the step and the time. Output files are
/// flushed before it is thrown out of the solver.
class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An output file could not be written during the run (a full disk, a removed folder): the run stops
/// with exit code 3 and "output failure: ... while writing FILE"; what was written before stays.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// OutputError naming the file, errno's reason (e.g. "No space left on device") and the fix.
OutputError output_failure(const std::string& path, int error_number);

/// Parallel runs: another rank met an error (it prints the one message); this rank stops with the
/// same exit code and prints nothing.
class StoppedByOtherRank : public std::runtime_error {
 public:
  explicit StoppedByOtherRank(int code) : std::runtime_error("stopped by another rank"), exit_code(code) {}
  int exit_code;
};

}  // namespace tribex::solver
