// SPDX-License-Identifier: MIT
// Who ran what, where and when: printed at the top of log.txt and written to summary.json, so that
// a result can be traced to the binary, the deck and the machine that made it.
#pragma once

#include <string>

namespace tribex::solver {

struct RunIdentity {
  std::string version;      // tribex version and `git describe` at build time (build_info.hpp)
  std::string deck_path;    // the deck file as given on the command line
  std::string deck_sha256;  // SHA-256 of the deck file's bytes (included files not hashed), or "" if unreadable
  std::string started_utc;  // ISO 8601, e.g. 2026-11-24T16:20:05Z
  std::string host;         // gethostname()
  int ranks = 1;            // MPI ranks
  std::string run_id;       // 32 hex digits, random; a run resumed from a restart file keeps its run's
  std::string mesh_sha256;  // of the mesh's coordinates and connectivity (solver/restart/run_fingerprint.hpp)
};

RunIdentity identify_run(const std::string& deck_path, int ranks);

/// One log line: "tribex VERSION | run RUNID | deck PATH (sha256 ...) | started ... on HOST | N rank(s) | energies in J".
std::string identity_line(const RunIdentity& id);

}  // namespace tribex::solver
