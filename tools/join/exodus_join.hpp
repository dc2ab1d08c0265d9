// SPDX-License-Identifier: MIT
// `tribex join OUT`: the per-rank results files of a parallel run (OUT/results.exo.N.r, Nemesis
// "spread" layout: solver/output/README.md "Exodus II output") joined into one OUT/results.exo, the
// file a one-rank run writes (README.md here).
#pragma once

#include <string>

namespace tribex::join {

struct JoinReport {
  int ranks = 0, steps = 0;  // ranks: of the last segment
  int segments = 1;          // the run's segments joined (rank counts in turn: a run resumed on another)
  long long nodes = 0, elements = 0;
  std::string path;  // the joined file
};

/// Joins OUT/results.exo.N.r (r = 0..N-1; N found from the names, or `ranks` when > 0) into
/// OUT/results.exo; when the folder holds the files of several rank counts and no `ranks` is given, the
/// segments of the run its manifest lists (a run resumed on another rank count), each rank count's steps
/// from its segment's start to the next one's, in time order, through OUT/.results.exo.partial and a rename: on any error nothing is left
/// half-written. Memory: the whole mesh plus one variable of one step (never grows with the steps).
/// tools::BadInput (one line, naming the file) for a missing, unreadable, truncated or inconsistent
/// rank file, or a results.exo there that no run or join of this folder wrote.
JoinReport join_rank_files(const std::string& folder, int ranks = 0);

}  // namespace tribex::join
