// SPDX-License-Identifier: MIT
// Pieces of parallel runs and restarts that need no mpiexec: the METIS element partition, the
// one-rank Domain, the restart file round trip and history.csv continuation. The runs under
// mpiexec are in tests/parallel (label mpi).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "mesh/box.hpp"
#include "cube_mesh.hpp"
#include "solver/output/history_writer.hpp"
#include "solver/parallel/domain.hpp"
#include "solver/parallel/partition.hpp"
#include "solver/restart/state_archive.hpp"

using namespace tribex;
using tribex::test::cube_mesh;

namespace {

std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("tribex_parallel_unit_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(Partition, OnePartIsAllZeros) {
  const auto part = solver::parallel::partition_elements(cube_mesh(4), 1);
  ASSERT_EQ(part.size(), 64u);
  EXPECT_EQ(std::count(part.begin(), part.end(), 0), 64);
}

TEST(Partition, KwayPartsAreBalancedAndRepeatable) {
  const auto m = cube_mesh(10);
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
  EXPECT_THROW(solver::parallel::partition_elements(cube_mesh(1), 2), std::runtime_error);
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

const std::vector<solver::ColumnInfo> columns = {
    {"step", "count", "step index"}, {"time", "s", "simulated time"}, {"extra", "N", "a force, with a comma"}};

TEST(HistoryWriter, ResumeKeepsTheRowsBeforeTheRestartStep) {
  const auto dir = temp_dir("history");
  const std::string path = (dir / "history.csv").string();
  {
    solver::HistoryWriter h(path, columns);
    for (long n = 0; n < 5; ++n) h.write_row(n, std::vector<double>(2, double(n)));
  }
  {
    solver::HistoryWriter h(path, columns, 3);  // resumed at step 3: rows 0, 1, 2 kept
    h.write_row(3, std::vector<double>(2, 30.0));
  }
  std::ifstream in(path);
  std::string line;
  std::vector<long> steps;
  std::getline(in, line);  // header
  while (std::getline(in, line)) steps.push_back(std::stol(line));
  EXPECT_EQ(steps, (std::vector<long>{0, 1, 2, 3}));
}

TEST(HistoryWriter, RowsMustFillEveryColumnAndUnitsGoBeside) {
  const auto dir = temp_dir("history_units");
  const std::string path = (dir / "history.csv").string();
  solver::HistoryWriter h(path, columns);
  EXPECT_THROW(h.write_row(0, std::vector<double>(1, 0.0)), std::logic_error);  // never padded
  EXPECT_THROW(h.write_row(0, std::vector<double>(3, 0.0)), std::logic_error);  // never dropped
  std::ifstream units((dir / "history_columns.csv").string());
  std::stringstream text;
  text << units.rdbuf();
  EXPECT_EQ(text.str(), "column,unit,definition\nstep,count,step index\ntime,s,simulated time\n"
                        "extra,N,\"a force, with a comma\"\n");
}

TEST(HistoryColumns, EveryStandardColumnHasAUnitAndADefinition) {
  const auto described = solver::describe_history_columns(true, {"top"}, {"tip"}, true);
  ASSERT_EQ(described.size(), 1 + solver::history_columns().size() + 6);
  std::set<std::string> names;
  for (const auto& c : described) {
    EXPECT_FALSE(c.unit.empty()) << c.name;
    EXPECT_GT(c.definition.size(), 5u) << c.name;
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate column " << c.name;
  }
  EXPECT_EQ(described.back().name, "tip_displacement_z");
  EXPECT_EQ(described[described.size() - 4].unit, "N");  // top_reaction_z
  // plastic_dissipation only where a material dissipates, added_mass only with mass scaling
  EXPECT_EQ(solver::describe_history_columns(false, {}, {}).size(), solver::history_columns().size() - 1);
  EXPECT_EQ(solver::describe_history_columns(false, {}, {}, true).back().name, "added_mass");
  EXPECT_EQ(solver::describe_history_columns(true, {}, {}).back().name, "plastic_dissipation");
}
