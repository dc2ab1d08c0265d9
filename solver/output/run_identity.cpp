// SPDX-License-Identifier: MIT
#include "solver/output/run_identity.hpp"

#include <unistd.h>

#include <climits>
#include <ctime>
#include <stdexcept>

#include "inputs/sha256.hpp"
#include "solver/output/build_info.hpp"

namespace tribex::solver {

RunIdentity identify_run(const std::string& deck_path, int ranks) {
  RunIdentity id;
  id.version = build_describe();
  id.deck_path = deck_path;
  try {
    id.deck_sha256 = inputs::sha256_file(deck_path);
  } catch (const std::runtime_error&) {
    id.deck_sha256.clear();  // a deck parsed from text (tests) has no file to hash
  }
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", &utc);
  id.started_utc = stamp;
  char host[HOST_NAME_MAX + 1] = {};
  if (gethostname(host, sizeof host - 1) == 0) id.host = host;
  id.ranks = ranks;
  return id;
}

std::string identity_line(const RunIdentity& id) {
  return "tribex " + id.version + " | run " + id.run_id + " | deck " + id.deck_path +
         (id.deck_sha256.empty() ? std::string() : " (sha256 " + id.deck_sha256 + ")") + " | started " +
         id.started_utc + " on " + (id.host.empty() ? std::string("an unnamed host") : id.host) + " | " +
         std::to_string(id.ranks) + (id.ranks == 1 ? " rank" : " ranks") + " | energies in J";
}

}  // namespace tribex::solver
