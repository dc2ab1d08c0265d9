// SPDX-License-Identifier: MIT
// `tribex join OUT [--ranks N]`: the per-rank Exodus results of a parallel run joined into OUT/results.exo.
#include <cstdio>
#include <string>
#include <vector>

#include "tools/cli/commands.hpp"
#include "tools/common/command.hpp"
#include "tools/join/exodus_join.hpp"

namespace tribex::cli {
namespace {

using namespace tools::command;

const char* join_usage =
    "usage: tribex join OUT [--ranks N]\n"
    "Joins the per-rank results files of a parallel run, OUT/results.exo.N.0 .. OUT/results.exo.N.(N-1)\n"
    "(format = exodus or both in `begin results output`), into OUT/results.exo: the file a one-rank run\n"
    "writes (coordinates, connectivity, blocks, node and side sets, every variable at every step), as\n"
    "SEACAS epu does. Written through OUT/.results.exo.partial and a rename; a missing or incomplete rank\n"
    "file is exit 2 with nothing written. ParaView opens the per-rank files as one data set too.\n"
    "A run resumed on another rank count leaves the files of each (results.exo.N.r, results.exo.M.r): the\n"
    "join takes each rank count's steps from its segment's start (the restart time) to the next one's, as\n"
    "the folder's manifest lists the segments, into one results.exo.\n"
    "  --ranks N   join the files of N ranks only, all their steps\n";

}  // namespace

int join_command(const std::vector<std::string>& args) {
  Args a(args, "tribex join", join_usage);
  if (a.answered_help()) return tools::exit_ok;
  const std::string folder = a.positional(0, "OUT");
  const long ranks = a.integer("--ranks", 0);
  a.finish();
  if (a.positional_count() != 1)
    throw BadInput("tribex join takes one output folder, got " + std::to_string(a.positional_count()));
  if (ranks < 0 || ranks > 1000000) throw BadInput("tribex join: --ranks must be a positive rank count, got " + std::to_string(ranks));
  const join::JoinReport r = join::join_rank_files(folder, static_cast<int>(ranks));
  if (r.segments > 1)
    std::printf("joined %d run segments (the last on %d ranks) into %s: %lld nodes, %lld elements, %d steps\n", r.segments,
                r.ranks, r.path.c_str(), r.nodes, r.elements, r.steps);
  else
    std::printf("joined %d rank files into %s: %lld nodes, %lld elements, %d steps\n", r.ranks, r.path.c_str(), r.nodes,
                r.elements, r.steps);
  return tools::exit_ok;
}

}  // namespace tribex::cli
