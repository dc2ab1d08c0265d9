// SPDX-License-Identifier: MIT
// ExodusWriter (results.exo) read back with the Exodus C API: the sample case's mesh and three
// steps (component names and values, stress order, globals), a file readable after a crash (fork,
// never closed), one-line SetupErrors, bad steps rejected, the mesh part readable as a mesh, and a
// resumed run keeping only the steps before its restart time.
#include <gtest/gtest.h>
#include <exodusII.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mesh/exodus_io.hpp"
#include "sample_case.hpp"
#include "solver/errors.hpp"
#include "solver/output/exodus_writer.hpp"
#include "tests/support/crashed_child.hpp"
#include "tests/support/setup_errors.hpp"

namespace {

namespace fs = std::filesystem;
using tribex::solver::ExodusWriter;
using tribex::solver::SetupError;
using tribex::test::make_hand_box;
using tribex::test::SampleFields;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tribex_exodus_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d;
}

const std::vector<std::string> global_names = {"step", "kinetic_energy"};

void write_sample_step(ExodusWriter& w, const tribex::mesh::Mesh& mesh, double t) {
  SampleFields f;
  f.fill(mesh, t);
  const auto nodal = f.nodal();
  const auto element = f.element();
  const std::vector<double> globals = {10 * t, 2 * t};
  w.write_step(t, nodal, element, globals);
}

struct Opened {
  int id = -1;
  explicit Opened(const fs::path& p) {
    int comp = 8, io = 0;
    float version = 0;
    id = ex_open(p.c_str(), EX_READ, &comp, &io, &version);
    if (id >= 0) ex_set_max_name_length(id, 64);
  }
  ~Opened() {
    if (id >= 0) ex_close(id);
  }
  std::vector<std::string> names(ex_entity_type type) const {
    int n = 0;
    ex_get_variable_param(id, type, &n);
    std::vector<std::vector<char>> b(static_cast<std::size_t>(n), std::vector<char>(65, '\0'));
    std::vector<char*> p;
    for (auto& x : b) p.push_back(x.data());
    if (n > 0) ex_get_variable_names(id, type, n, p.data());
    std::vector<std::string> out;
    for (auto& x : b) out.emplace_back(x.data());
    return out;
  }
  std::vector<double> times() const {
    std::vector<double> t(static_cast<std::size_t>(ex_inquire_int(id, EX_INQ_TIME)));
    if (!t.empty()) ex_get_all_times(id, t.data());
    return t;
  }
};

TEST(ExodusWriter, ComponentNamesAreTheExodusConvention) {
  EXPECT_EQ(ExodusWriter::component_names("u", 1), std::vector<std::string>{"u"});
  EXPECT_EQ(ExodusWriter::component_names("u", 3), (std::vector<std::string>{"u_x", "u_y", "u_z"}));
  EXPECT_EQ(ExodusWriter::component_names("s", 6),
            (std::vector<std::string>{"s_xx", "s_yy", "s_zz", "s_xy", "s_yz", "s_zx"}));
  EXPECT_EQ(ExodusWriter::component_names("f", 9).at(2), "f_xz");
  EXPECT_EQ(ExodusWriter::component_names("slip", 2), (std::vector<std::string>{"slip_1", "slip_2"}));
}

TEST(ExodusWriter, MeshAndThreeStepsReadBack) {
  const fs::path dir = fresh_dir("readback");
  const auto mesh = make_hand_box(3, 2, 2);
  {
    ExodusWriter w(dir.string(), mesh, global_names);
    for (double t : tribex::test::sample_times) write_sample_step(w, mesh, t);
    EXPECT_EQ(w.step_count(), 3);
  }
  // The mesh part is a mesh file.
  const auto back = tribex::mesh::read_exodus((dir / "results.exo").string());
  EXPECT_EQ(back.coordinates, mesh.coordinates);
  EXPECT_EQ(back.connectivity, mesh.connectivity);
  ASSERT_EQ(back.blocks.size(), 2u);
  EXPECT_EQ(back.blocks[1].name, "asperity");

  Opened f(dir / "results.exo");
  ASSERT_GE(f.id, 0);
  EXPECT_EQ(f.times(), tribex::test::sample_times);
  EXPECT_EQ(f.names(EX_GLOBAL), global_names);
  EXPECT_EQ(f.names(EX_NODAL), (std::vector<std::string>{"displacement_x", "displacement_y", "displacement_z", "temperature"}));
  EXPECT_EQ(f.names(EX_ELEM_BLOCK), (std::vector<std::string>{"stress_xx", "stress_yy", "stress_zz", "stress_xy",
                                                              "stress_yz", "stress_zx", "plastic_strain", "slip_1",
                                                              "slip_2"}));
  SampleFields want;
  want.fill(mesh, 0.5);
  const int n = mesh.node_count();
  std::vector<double> v(static_cast<std::size_t>(n));
  ASSERT_GE(ex_get_var(f.id, 3, EX_NODAL, 2, 1, n, v.data()), 0);  // displacement_y at step 3
  for (int a = 0; a < n; ++a) EXPECT_EQ(v[a], want.displacement[3 * a + 1]);
  // stress_zx (variable 6) of block 2 (asperity, elements 6..11): Voigt component 5.
  std::vector<double> s(6);
  ASSERT_GE(ex_get_var(f.id, 3, EX_ELEM_BLOCK, 6, 2, 6, s.data()), 0);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(s[k], want.stress[6 * (6 + k) + 5]);
  std::vector<double> g(2);
  ASSERT_GE(ex_get_glob_vars(f.id, 2, 2, g.data()), 0);
  EXPECT_EQ(g, (std::vector<double>{2.5, 0.5}));
  fs::remove_all(dir);
}

TEST(ExodusWriter, FileIsReadableAfterACrashMidRun) {
  const fs::path dir = fresh_dir("crash");
  const auto mesh = make_hand_box(2, 1, 1);
  ASSERT_TRUE(tribex::test::ran_in_child_left_unclosed([&] {
    auto* w = new ExodusWriter(dir.string(), mesh, global_names);  // leaked on purpose: never closed
    for (double t : {0.0, 0.25}) write_sample_step(*w, mesh, t);
  }));
  Opened f(dir / "results.exo");
  ASSERT_GE(f.id, 0);
  EXPECT_EQ(f.times(), (std::vector<double>{0.0, 0.25}));
  std::vector<double> v(static_cast<std::size_t>(mesh.node_count()));
  ASSERT_GE(ex_get_var(f.id, 2, EX_NODAL, 1, 1, mesh.node_count(), v.data()), 0);
  EXPECT_EQ(v.back(), 0.25 * mesh.coordinates[3 * (mesh.node_count() - 1)]);
  fs::remove_all(dir);
}

TEST(ExodusWriter, UncreatableDirectoryOrFileIsAOneLineSetupError) {
  const fs::path dir = fresh_dir("blocked");
  const std::string bad = tribex::test::path_under_a_file(dir);
  std::string msg = tribex::test::setup_error_of([&] { ExodusWriter w(bad, make_hand_box(1, 1, 1), global_names); });
  EXPECT_NE(msg.find(bad), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  fs::create_directories(dir / "run" / "results.exo");  // a folder where the file should go
  msg = tribex::test::setup_error_of(
      [&] { ExodusWriter w((dir / "run").string(), make_hand_box(1, 1, 1), global_names); });
  EXPECT_NE(msg.find((dir / "run" / "results.exo").string()), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(ExodusWriter, BadStepsAreRejected) {
  const fs::path dir = fresh_dir("bad");
  const auto mesh = make_hand_box(2, 1, 1);
  ExodusWriter w(dir.string(), mesh, global_names);
  write_sample_step(w, mesh, 0.0);
  SampleFields f;
  f.fill(mesh, 1.0);
  const auto nodal = f.nodal();
  const auto element = f.element();
  const std::vector<double> globals = {1, 2};
  EXPECT_THROW(w.write_step(1.0, nodal, element, std::vector<double>{1}), std::invalid_argument);  // globals
  EXPECT_THROW(w.write_step(1.0, std::span(nodal).first(1), element, globals), std::invalid_argument);  // a field less
  EXPECT_THROW(w.write_step(0.0, nodal, element, globals), std::invalid_argument);  // time not increasing
  EXPECT_EQ(w.step_count(), 1);
  w.write_step(1.0, nodal, element, globals);  // still usable
  EXPECT_EQ(w.step_count(), 2);
  fs::remove_all(dir);
}

TEST(ExodusWriter, ResumedRunKeepsTheStepsBeforeItsRestartTime) {
  const fs::path dir = fresh_dir("resume");
  const auto mesh = make_hand_box(2, 1, 2);
  {
    ExodusWriter w(dir.string(), mesh, global_names);
    for (double t : {0.0, 0.25, 0.5, 0.75}) write_sample_step(w, mesh, t);
  }
  {
    ExodusWriter w(dir.string(), mesh, global_names, 0.5);  // restart at t = 0.5
    EXPECT_EQ(w.step_count(), 2);
    write_sample_step(w, mesh, 0.5);
  }
  Opened f(dir / "results.exo");
  ASSERT_GE(f.id, 0);
  EXPECT_EQ(f.times(), (std::vector<double>{0.0, 0.25, 0.5}));
  std::vector<double> g(2);
  ASSERT_GE(ex_get_glob_vars(f.id, 2, 2, g.data()), 0);
  EXPECT_EQ(g, (std::vector<double>{2.5, 0.5}));  // copied step
  EXPECT_FALSE(fs::exists(dir / ".results.exo.partial"));
  // Another mesh's file is refused and left alone.
  const auto size = fs::file_size(dir / "results.exo");
  EXPECT_THROW(ExodusWriter(dir.string(), make_hand_box(3, 1, 2), global_names, 0.5), SetupError);
  EXPECT_EQ(fs::file_size(dir / "results.exo"), size);
  fs::remove_all(dir);
}

}  // namespace
