// SPDX-License-Identifier: MIT
// Restart files written in parallel (issue 57 scope 3; solver/restart/restart_file.cpp): all ranks write one
// file at once with parallel HDF5, each its own group; every group reads back bit for bit, whatever the
// ranks' entry sizes (empty arrays, an entry only some ranks have), and a write that fails is a
// NumericalFailure on every rank with no file left under the final name.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "solver/errors.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {
namespace {

// Rank r's archive: arrays of r-dependent sizes and values (1/3 and huge/tiny magnitudes: any rounding
// would show), scalars, an empty array, an entry only the odd ranks have, one empty on the last rank only.
StateArchive archive_of(int r, int round) {
  StateArchive a;
  std::vector<double> u;
  for (int k = 0; k < 3 * (r + 1) + round; ++k) u.push_back((r * 1000 + k) / 3.0 * (k % 2 ? 1e-300 : 6.02214076e23));
  a.put("u", u);
  a.put("time", 1.25e-11 * (round + 1));
  a.put("empty", std::vector<double>{});
  a.put_integer("step", 123456789012LL + round);
  std::vector<long long> ids;
  for (int k = 0; k < 2 * r; ++k) ids.push_back(-7 + 1000LL * r + k);
  a.put_integers("global_node", ids);
  if (r % 2 == 1) a.put("only_odd", std::vector<double>{-0.0, 2.5 * r});
  // Empty on the last rank only: its slice starts at the dataset's end.
  a.put("tail", r + 1 == parallel::size() ? std::vector<double>{} : std::vector<double>{1.0 * r, -2.0 * r});
  return a;
}

std::filesystem::path shared_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("tribex_restart_mpi_np" + std::to_string(parallel::size()) + "_" + name);
  if (parallel::is_root()) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  parallel::barrier();
  return dir;
}

// Written twice into the same path (the ring reuses its files: the second write truncates the first's
// .part and replaces the file), then every rank reads every group.
TEST(RestartFileParallel, EveryGroupReadsBackBitForBit) {
  const std::string path = (shared_dir("roundtrip") / "restart.h5").string();
  for (int round = 0; round < 2; ++round) write_restart_file(path, archive_of(parallel::rank(), round), "run-abc");
  EXPECT_FALSE(std::filesystem::exists(path + ".part"));
  const RestartFile file(path);
  ASSERT_EQ(file.ranks(), parallel::size());
  for (int g = 0; g < parallel::size(); ++g) {
    const StateArchive expected = archive_of(g, 1), read = file.read_group(g);
    EXPECT_EQ(read.reals, expected.reals) << "group " << g;  // bit for bit (-0.0 == 0.0 aside: checked below)
    EXPECT_EQ(read.integers, expected.integers) << "group " << g;
    EXPECT_EQ(read.has("only_odd"), g % 2 == 1) << "group " << g;
    if (g % 2 == 1) {
      EXPECT_TRUE(std::signbit(read.array("only_odd")[0]));
    }
  }
  EXPECT_EQ(read_restart_file(path).array("u"), archive_of(parallel::rank(), 1).array("u"));
}

// A folder that does not exist: the open fails (collectively), every rank throws, none waits for another.
TEST(RestartFileParallel, FailedWriteIsANumericalFailureOnEveryRank) {
  const std::string path = (shared_dir("failure") / "missing" / "restart.h5").string();
  try {
    write_restart_file(path, archive_of(parallel::rank(), 0));
    FAIL() << "the write into a missing folder succeeded";
  } catch (const NumericalFailure& e) {
    EXPECT_NE(std::string(e.what()).find("could not write the restart file " + path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  // The ranks still agree afterwards: a write that works.
  const std::string good = (shared_dir("after_failure") / "restart.h5").string();
  write_restart_file(good, archive_of(parallel::rank(), 0));
  EXPECT_EQ(RestartFile(good).read_group(parallel::size() - 1).reals, archive_of(parallel::size() - 1, 0).reals);
}

}  // namespace
}  // namespace tribex::solver
