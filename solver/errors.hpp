// SPDX-License-Identifier: MIT
#pragma once

#include <exception>
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

/// OutputError naming the file, errno's reason and the fix; a full device (ENOSPC, EDQUOT) reads
/// "no space left on device (N bytes free in FOLDER)".
OutputError output_failure(const std::string& path, int error_number);

/// "no space left on device (N bytes free in FOLDER)" for a file `what` (FOLDER: its folder).
std::string no_space_reason(const std::string& what);

/// Parallel runs: another rank met an error (it prints the one message); this rank stops with the
/// same exit code and prints nothing.
class StoppedByOtherRank : public std::runtime_error {
 public:
  explicit StoppedByOtherRank(int code) : std::runtime_error("stopped by another rank"), exit_code(code) {}
  int exit_code;
};

/// The mesh node (0-based) that belongs to no element: it would have no mass.
SetupError orphan_node_error(int node);

/// Exit code of an error (2 bad input, 3 numerical failure, a StoppedByOtherRank's own, else 1).
int exit_code_of(const std::exception_ptr& error);

/// Collective: when any rank holds an error, the lowest such rank rethrows it (and prints it) and
/// every other rank throws StoppedByOtherRank with its exit code. For the steps of the set-up that
/// can fail on some ranks only (a rank's part of the mesh, files written by rank 0, a rank's group of
/// a restart file). One rank: rethrows its error.
void agree_on_errors(const std::exception_ptr& error);

}  // namespace tribex::solver
