// SPDX-License-Identifier: MIT
// Pieces of parallel runs and restarts that need no mpiexec: the METIS element partition, the
// one-rank Domain, the restart file round trip and history.csv continuation. The runs under
// mpiexec are in tests/parallel (label mpi).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mesh/box.hpp"
#include "solver/output/history_writer.hpp"
#include "solver/parallel/domain.hpp"
#include "solver/parallel/partition.hpp"
#include "solver/restart/state_archive.hpp"

using namespace tribex;

namespace {

mesh::Mesh box(int n) {
  mesh::BoxSpec spec;
  spec.intervals = {n, n, n};
  return mesh::generate_box(spec);
}

std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("tribex_parallel_unit_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(Partition, OnePartIsAllZeros) {
  const auto part = solver::parallel::partition_elements(box(4), 1);
  ASSERT_EQ(part.size(), 64u);
  EXPECT_EQ(std::count(part.begin(), part.end(), 0), 64);
}

TEST(Partition, KwayPartsAreBalancedAndRepeatable) {
  const auto m = box(10);
  for (int parts : {2, 4}) {
    const auto a = solver::parallel::partition_elements(m, parts);
    const auto b = solver::parallel::partition_elements(m, parts);
    EXPECT_EQ(a, b) << "every rank must compute the same partition";
    for (int p = 0; p < parts; ++p) {
      const double share = double(std::count(a.begin(), a.end(), p)) / 1000.0;
      // METIS' default load imbalance tolerance is 3 %.
      EXPECT_NEAR(share, 1.0 / parts, 0.031 / parts) << parts << " parts, part " << p;
    }
  }
}

TEST(Partition, MorePartsThanElementsIsAnError) {
  EXPECT_THROW(solver::parallel::partition_elements(box(1), 2), std::runtime_error);
}

TEST(Domain, SerialDomainIsTheIdentity) {
  solver::parallel::Domain d;
  d.init_serial(5, 2);
  EXPECT_TRUE(d.serial());
  EXPECT_EQ(d.global_node, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(d.owned_local_nodes(), d.global_node);
  EXPECT_EQ(d.owned, std::vector<double>(5, 1.0));
  double f[15];
  for (int i = 0; i < 15; ++i) f[i] = i;
  d.sum_shared(f);  // nothing shared: unchanged
  for (int i = 0; i < 15; ++i) EXPECT_EQ(f[i], i);
}

TEST(RestartFile, RoundTripIsExact) {
  const auto dir = temp_dir("roundtrip");
  solver::StateArchive a;
  a.put("u", std::vector<double>{1.0 / 3.0, -2.5e-300, 6.02214076e23});
  a.put("time", 1.25e-11);
  a.put_integer("step", 123456789012LL);
  a.put_ints("faces", std::vector<int>{-1, 0, 7});
  a.put("empty", std::vector<double>{});
  const std::string path = (dir / "restart.h5").string();
  solver::write_restart_file(path, a);
  ASSERT_FALSE(std::filesystem::exists(path + ".part"));
  const auto b = solver::read_restart_file(path);
  EXPECT_EQ(b.reals, a.reals);  // bit for bit
  EXPECT_EQ(b.integers, a.integers);
  EXPECT_EQ(b.integer("step"), 123456789012LL);
  std::vector<double> wrong(2);
  EXPECT_THROW(b.get("u", wrong), solver::SetupError);
  EXPECT_THROW(b.array("missing"), solver::SetupError);
}

TEST(RestartFile, MissingOrForeignFileIsBadInput) {
  const auto dir = temp_dir("bad");
  EXPECT_THROW(solver::read_restart_file((dir / "nope.h5").string()), solver::SetupError);
  std::ofstream((dir / "text.h5").string()) << "not hdf5\n";
  EXPECT_THROW(solver::read_restart_file((dir / "text.h5").string()), solver::SetupError);
}

TEST(HistoryWriter, ResumeKeepsTheRowsBeforeTheRestartStep) {
  const auto dir = temp_dir("history");
  const std::string path = (dir / "history.csv").string();
  {
    solver::HistoryWriter h(path, {"extra"});
    for (long n = 0; n < 5; ++n) h.write_row(n, std::vector<double>(40, double(n)));
  }
  {
    solver::HistoryWriter h(path, {"extra"}, 3);  // resumed at step 3: rows 0, 1, 2 kept
    h.write_row(3, std::vector<double>(40, 30.0));
  }
  std::ifstream in(path);
  std::string line;
  std::vector<long> steps;
  std::getline(in, line);  // header
  while (std::getline(in, line)) steps.push_back(std::stol(line));
  EXPECT_EQ(steps, (std::vector<long>{0, 1, 2, 3}));
}
