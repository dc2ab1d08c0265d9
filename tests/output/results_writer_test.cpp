// SPDX-License-Identifier: MIT
// ResultsWriter: read the HDF5 file back with the C API, check the XDMF text, crash safety and
// error paths. The ParaView read is the separate CTest check_xdmf_paraview (see CMakeLists.txt).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "sample_case.hpp"
#include "solver/errors.hpp"
#include "solver/output/results_writer.hpp"
#include "tests/support/crashed_child.hpp"
#include "tests/support/setup_errors.hpp"

namespace fs = std::filesystem;
using tribex::solver::FieldView;
using tribex::solver::ResultsWriter;
using tribex::solver::SetupError;
using tribex::test::make_hand_box;
using tribex::test::SampleFields;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tribex_output_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A dataset read back whole: dims and values converted to double.
struct Array {
  std::vector<hsize_t> dims;
  std::vector<double> values;
};

Array read_dataset(hid_t file, const std::string& path) {
  Array a;
  const hid_t d = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (d < 0) throw std::runtime_error("no dataset " + path);
  const hid_t s = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(s);
  a.dims.resize(std::size_t(rank));
  H5Sget_simple_extent_dims(s, a.dims.data(), nullptr);
  a.values.resize(std::size_t(H5Sget_simple_extent_npoints(s)));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.values.data());
  H5Sclose(s);
  H5Dclose(d);
  return a;
}

double read_time(hid_t file, const std::string& group) {
  double t = -1;
  const hid_t a = H5Aopen_by_name(file, group.c_str(), "time", H5P_DEFAULT, H5P_DEFAULT);
  H5Aread(a, H5T_NATIVE_DOUBLE, &t);
  H5Aclose(a);
  return t;
}

/// True when every link on the absolute path exists (H5Lexists needs its parents to exist).
bool h5_path_exists(hid_t file, const std::string& path) {
  std::string prefix;
  std::stringstream parts(path.substr(1));
  for (std::string part; std::getline(parts, part, '/');) {
    prefix += "/" + part;
    if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return !prefix.empty();
}

/// Minimal XML check: every start tag has its end tag in order; returns "" or the problem.
std::string xml_balance_problem(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t pos = xml.find('<'); pos != std::string::npos; pos = xml.find('<', pos + 1)) {
    const std::size_t end = xml.find('>', pos);
    if (end == std::string::npos) return "unterminated tag at byte " + std::to_string(pos);
    const std::string tag = xml.substr(pos + 1, end - pos - 1);
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name) return "unexpected </" + name + "> at byte " + std::to_string(pos);
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
    }
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

std::vector<std::string> h5_references(const std::string& xml) {
  std::vector<std::string> refs;
  const std::regex item(R"(Format="HDF">results\.h5:([^<]+)</DataItem>)");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), item); it != std::sregex_iterator(); ++it)
    refs.push_back((*it)[1]);
  return refs;
}

/// Writes the sample fields at time t as one step.
template <class Mesh>
void write_sample_step(ResultsWriter& w, const Mesh& mesh, double t) {
  SampleFields f;
  f.fill(mesh, t);
  auto nodal = f.nodal();
  auto element = f.element();
  w.write_step(t, nodal, element);
}

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

}  // namespace

TEST(ResultsWriter, MeshAndThreeStepsReadBackWithHdf5) {
  const fs::path dir = fresh_dir("readback");
  tribex::test::write_sample_case(dir.string());
  const auto mesh = make_hand_box(3, 2, 2);  // 36 nodes, 12 elements
  const hid_t f = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);

  const Array xyz = read_dataset(f, "/mesh/coordinates");
  EXPECT_EQ(xyz.dims, (std::vector<hsize_t>{36, 3}));
  EXPECT_EQ(xyz.values, mesh.coordinates);
  const Array conn = read_dataset(f, "/mesh/connectivity");
  EXPECT_EQ(conn.dims, (std::vector<hsize_t>{12, 8}));
  EXPECT_EQ(conn.values, std::vector<double>(mesh.connectivity.begin(), mesh.connectivity.end()));
  const Array block = read_dataset(f, "/mesh/block_id");
  EXPECT_EQ(block.dims, (std::vector<hsize_t>{12}));
  for (int e = 0; e < 12; ++e) EXPECT_EQ(block.values[e], e < 6 ? 0 : 1) << "element " << e;

  SampleFields expected;
  for (int s = 0; s < 3; ++s) {
    const double t = tribex::test::sample_times[s];
    expected.fill(mesh, t);
    const std::string g = "/steps/step_00000" + std::to_string(s);
    EXPECT_EQ(read_time(f, g), t);
    const Array u = read_dataset(f, g + "/nodal/displacement");
    EXPECT_EQ(u.dims, (std::vector<hsize_t>{36, 3}));
    EXPECT_EQ(u.values, expected.displacement);
    const Array temp = read_dataset(f, g + "/nodal/temperature");
    EXPECT_EQ(temp.dims, (std::vector<hsize_t>{36}));
    EXPECT_EQ(temp.values, expected.temperature);
    // Voigt xx yy zz xy yz zx is stored as the full row-major tensor xx xy xz yx yy yz zx zy zz.
    const Array sig = read_dataset(f, g + "/element/stress");
    ASSERT_EQ(sig.dims, (std::vector<hsize_t>{12, 9}));
    const int voigt[9] = {0, 3, 5, 3, 1, 4, 5, 4, 2};
    for (int e = 0; e < 12; ++e)
      for (int k = 0; k < 9; ++k)
        EXPECT_EQ(sig.values[9 * e + k], expected.stress[6 * e + voigt[k]]) << "element " << e << " entry " << k;
    EXPECT_EQ(sig.values[9 * 4 + 1], 5 * (1 + t) * 4);  // element 4, xy = (e+1)(1+t)*4
    EXPECT_EQ(read_dataset(f, g + "/element/plastic_strain").values, expected.plastic_strain);
    const Array slip = read_dataset(f, g + "/element/slip");
    EXPECT_EQ(slip.dims, (std::vector<hsize_t>{12, 2}));
    EXPECT_EQ(slip.values, expected.slip);
  }
  H5Fclose(f);
  fs::remove_all(dir);
}

TEST(ResultsWriter, XdmfIsWellFormedAndNamesOnlyExistingDatasets) {
  const fs::path dir = fresh_dir("xdmf");
  tribex::test::write_sample_case(dir.string());
  const std::string xml = slurp(dir / "results.xdmf");
  EXPECT_EQ(xml_balance_problem(xml), "");
  EXPECT_FALSE(fs::exists(dir / "results.xdmf.tmp"));
  // One spatial collection of one temporal collection per block, named after it, of 3 step grids.
  EXPECT_EQ(count(xml, "CollectionType=\"Spatial\""), 1);
  EXPECT_EQ(count(xml, "<Grid Name=\"substrate\" GridType=\"Collection\" CollectionType=\"Temporal\">"), 1);
  EXPECT_EQ(count(xml, "<Grid Name=\"asperity\" GridType=\"Collection\" CollectionType=\"Temporal\">"), 1);
  EXPECT_EQ(count(xml, "<Time Value="), 3 * 2);
  EXPECT_EQ(count(xml, "<Grid Name=\"substrate\" GridType=\"Uniform\">"), 3);
  EXPECT_EQ(count(xml, "<Grid Name=\"asperity\" GridType=\"Uniform\">"), 3);
  EXPECT_NE(xml.find("<Time Value=\"0.25\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"0.5\"/>"), std::string::npos);
  // The mesh is named once per block; steps 1 and 2 include it by XPointer.
  EXPECT_EQ(count(xml, "results.h5:/mesh/coordinates"), 2);
  EXPECT_EQ(count(xml, "results.h5:/mesh/connectivity"), 2);
  EXPECT_EQ(count(xml, "<xi:include"), 2 * 2);
  // Cell data and topology: the block's rows of the whole array (6 elements each); nodal: whole.
  EXPECT_NE(xml.find("<Attribute Name=\"stress\" AttributeType=\"Tensor\" Center=\"Cell\"><Information Name=\"units\" "
                     "Value=\"Pa\"/><DataItem "
                     "ItemType=\"HyperSlab\" Dimensions=\"6 9\" Type=\"HyperSlab\" NumberType=\"Float\" Precision=\"8\">"
                     "<DataItem Dimensions=\"3 2\" NumberType=\"Int\" Format=\"XML\">6 0 1 1 6 9</DataItem>"),
            std::string::npos);
  EXPECT_NE(xml.find("<Attribute Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\"><Information Name=\"units\" "
                     "Value=\"m\"/><DataItem "
                     "Dimensions=\"36 3\""),
            std::string::npos);
  EXPECT_NE(xml.find("<Attribute Name=\"slip\" AttributeType=\"Matrix\" Center=\"Cell\"><Information Name=\"units\" "
                     "Value=\"m\"/><DataItem "
                     "ItemType=\"HyperSlab\" Dimensions=\"6 2\""),
            std::string::npos);
  EXPECT_NE(xml.find("<Attribute Name=\"plastic_strain\" AttributeType=\"Scalar\" Center=\"Cell\"><Information "
                     "Name=\"units\" Value=\"1\"/>"),
            std::string::npos);
  EXPECT_EQ(xml.find(" ["), std::string::npos);  // no name carries a bracketed unit
  EXPECT_NE(xml.find("<Information Name=\"length_unit\" Value=\"m\"/>"), std::string::npos);

  const auto refs = h5_references(xml);
  EXPECT_EQ(refs.size(), 2u * 3u + 2u * 3u * 5u);  // per block: mesh (3) + 5 fields x 3 steps
  const hid_t f = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const auto& r : refs) EXPECT_TRUE(h5_path_exists(f, r)) << r;
  EXPECT_FALSE(h5_path_exists(f, "/steps/step_000003"));  // the check itself can fail
  H5Fclose(f);
  fs::remove_all(dir);
}

TEST(ResultsWriter, BeforeAnyStepTheXdmfShowsTheMesh) {
  const fs::path dir = fresh_dir("nostep");
  {
    ResultsWriter w(dir.string(), make_hand_box(2, 2, 2));
    EXPECT_EQ(w.step_count(), 0);
  }
  const std::string xml = slurp(dir / "results.xdmf");
  EXPECT_EQ(xml_balance_problem(xml), "");
  EXPECT_EQ(count(xml, "<Grid "), 1 + 2);  // the mesh: one grid per block
  EXPECT_EQ(count(xml, "NumberOfElements=\"4\""), 2);
  EXPECT_NE(xml.find("Dimensions=\"27 3\""), std::string::npos);
  fs::remove_all(dir);
}

// A process killed after its second step (no destructor, no H5Fclose) leaves a readable pair.
TEST(ResultsWriter, PairIsReadableAfterACrashMidRun) {
  const fs::path dir = fresh_dir("crash");
  const auto mesh = make_hand_box(2, 1, 1);
  ASSERT_TRUE(tribex::test::ran_in_child_left_unclosed([&] {
    auto* w = new ResultsWriter(dir.string(), mesh);  // leaked on purpose: never closed
    SampleFields f;
    for (double t : {0.0, 0.25}) {
      f.fill(mesh, t);
      const auto n = f.nodal();
      const auto e = f.element();
      w->write_step(t, n, e);
    }
  }));
  const std::string xml = slurp(dir / "results.xdmf");
  EXPECT_EQ(xml_balance_problem(xml), "");
  EXPECT_EQ(count(xml, "<Time Value="), 2);  // a 2 x 1 x 1 box is one block
  const hid_t f = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const auto& r : h5_references(xml)) EXPECT_TRUE(h5_path_exists(f, r)) << r;
  SampleFields expected;
  expected.fill(mesh, 0.25);
  EXPECT_EQ(read_dataset(f, "/steps/step_000001/nodal/displacement").values, expected.displacement);
  H5Fclose(f);
  fs::remove_all(dir);
}

TEST(ResultsWriter, UncreatableDirectoryIsAOneLineSetupErrorWithPathAndReason) {
  const fs::path dir = fresh_dir("blocked");
  const std::string bad = tribex::test::path_under_a_file(dir);
  std::string msg = tribex::test::setup_error_of([&] { ResultsWriter w(bad, make_hand_box(1, 1, 1)); });
  EXPECT_NE(msg.find(bad), std::string::npos) << msg;
  EXPECT_NE(msg.find("Not a directory"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  // results.h5 exists as a directory: the file itself cannot be created.
  fs::create_directories(dir / "run" / "results.h5");
  msg = tribex::test::setup_error_of([&] { ResultsWriter w((dir / "run").string(), make_hand_box(1, 1, 1)); });
  EXPECT_NE(msg.find((dir / "run" / "results.h5").string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("Is a directory"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(ResultsWriter, BadStepsAreRejectedBeforeAnythingIsWritten) {
  const fs::path dir = fresh_dir("badstep");
  const auto mesh = make_hand_box(2, 2, 1);
  ResultsWriter w(dir.string(), mesh);
  SampleFields f;
  f.fill(mesh, 0.0);
  auto nodal = f.nodal();
  auto element = f.element();
  w.write_step(0.0, nodal, element);
  const std::string before = slurp(dir / "results.xdmf");

  EXPECT_THROW(w.write_step(0.0, nodal, element), std::invalid_argument);  // time not increasing
  auto short_u = nodal;
  short_u[0].values = short_u[0].values.first(short_u[0].values.size() - 1);
  EXPECT_THROW(w.write_step(1.0, short_u, element), std::invalid_argument);
  auto fewer = nodal;
  fewer.pop_back();
  EXPECT_THROW(w.write_step(1.0, fewer, element), std::invalid_argument);  // field set changed
  auto renamed = element;
  renamed[1].name = "bad/name";
  EXPECT_THROW(w.write_step(1.0, nodal, renamed), std::invalid_argument);
  auto clash = element;
  clash[1].name = "displacement";  // same name as a nodal field
  clash[1].components = 1;
  EXPECT_THROW(w.write_step(1.0, nodal, clash), std::invalid_argument);

  EXPECT_EQ(w.step_count(), 1);
  EXPECT_EQ(slurp(dir / "results.xdmf"), before);
  w.write_step(1.0, nodal, element);  // the writer is still usable
  EXPECT_EQ(w.step_count(), 2);
  fs::remove_all(dir);
}

TEST(ResultsWriter, ResumedRunContinuesTheFileFromItsRestartTime) {
  // Three steps at t = 0, 1, 2 written, then a run resumed at t = 1.5 keeps t = 0 and 1, drops
  // t = 2 and appends t = 2.5: the file and the XDMF read as those of one run through 0, 1, 2.5.
  const fs::path one = fresh_dir("resume_one"), two = fresh_dir("resume_two");
  const auto mesh = make_hand_box(2, 2, 1);
  const auto write = [&](ResultsWriter& w, double t) { write_sample_step(w, mesh, t); };
  {
    ResultsWriter w(one.string(), mesh);
    for (double t : {0.0, 1.0, 2.0}) write(w, t);
  }
  {
    ResultsWriter w(one.string(), mesh, nullptr, 1.5);
    EXPECT_EQ(w.step_count(), 2);
    write(w, 2.5);
    EXPECT_EQ(w.step_count(), 3);
  }
  {
    ResultsWriter w(two.string(), mesh);  // the uninterrupted run
    for (double t : {0.0, 1.0, 2.5}) write(w, t);
  }
  EXPECT_EQ(slurp(one / "results.xdmf"), slurp(two / "results.xdmf"));
  const hid_t a = H5Fopen((one / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t b = H5Fopen((two / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  for (const char* g : {"/steps/step_000000", "/steps/step_000001", "/steps/step_000002"}) {
    EXPECT_EQ(read_time(a, g), read_time(b, g)) << g;
    for (const char* d : {"/nodal/displacement", "/nodal/temperature", "/element/stress", "/element/slip"})
      EXPECT_EQ(read_dataset(a, std::string(g) + d).values, read_dataset(b, std::string(g) + d).values) << g << d;
  }
  EXPECT_FALSE(h5_path_exists(a, "/steps/step_000003"));
  H5Fclose(a);
  H5Fclose(b);
  fs::remove_all(one);
  fs::remove_all(two);
}

TEST(ResultsWriter, ResumingIntoAnotherMeshsFileIsASetupErrorAndLeavesItAlone) {
  const fs::path dir = fresh_dir("resume_other");
  const auto small = make_hand_box(2, 2, 1), large = make_hand_box(3, 2, 2);
  {
    ResultsWriter w(dir.string(), small);
    write_sample_step(w, small, 0.0);
  }
  const std::string before = slurp(dir / "results.xdmf");
  const auto size = fs::file_size(dir / "results.h5");
  try {
    ResultsWriter w(dir.string(), large, nullptr, 1.0);
    FAIL() << "no error";
  } catch (const SetupError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("results.h5"), std::string::npos) << what;
    EXPECT_NE(what.find("not the results file of this mesh"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_EQ(fs::file_size(dir / "results.h5"), size);
  EXPECT_EQ(slurp(dir / "results.xdmf"), before);
  // No file to continue: a resumed run starts a new one.
  const fs::path fresh = fresh_dir("resume_fresh");
  ResultsWriter w(fresh.string(), small, nullptr, 1.0);
  EXPECT_EQ(w.step_count(), 0);
  fs::remove_all(dir);
  fs::remove_all(fresh);
}

namespace {

std::string read_units(hid_t file, const std::string& object, const char* name = "units") {
  if (H5Aexists_by_name(file, object.c_str(), name, H5P_DEFAULT) <= 0) return "(none)";
  const hid_t a = H5Aopen_by_name(file, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t type = H5Aget_type(a);
  std::string value(H5Tget_size(type), '\0');
  H5Aread(a, type, value.data());
  H5Tclose(type);
  H5Aclose(a);
  return value.c_str();
}

}  // namespace

// A model 3 nm across (issue 27): auto writes the coordinates and the length fields in nm, every
// other field in SI, each dataset with its `units`; datasets are chunked with shuffle + deflate.
TEST(ResultsWriter, NanometreModelIsWrittenInNanometresWithUnitsOnEveryDataset) {
  const fs::path dir = fresh_dir("nm");
  auto mesh = make_hand_box(3, 2, 2);
  for (double& x : mesh.coordinates) x *= 1e-9;
  {
    ResultsWriter w(dir.string(), mesh);
    EXPECT_EQ(w.length_unit(), "nm");
    write_sample_step(w, mesh, 0.5);
  }
  const hid_t f = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_units(f, "/", "length_unit"), "nm");
  const Array xyz = read_dataset(f, "/mesh/coordinates");
  for (std::size_t i = 0; i < xyz.values.size(); ++i)
    EXPECT_NEAR(xyz.values[i], mesh.coordinates[i] * 1e9, 1e-14) << i;
  SampleFields si;
  si.fill(mesh, 0.5);
  const Array u = read_dataset(f, "/steps/step_000000/nodal/displacement");
  for (std::size_t i = 0; i < u.values.size(); ++i) EXPECT_NEAR(u.values[i], si.displacement[i] * 1e9, 1e-14) << i;
  EXPECT_EQ(read_dataset(f, "/steps/step_000000/nodal/temperature").values, si.temperature);  // K: untouched
  const std::pair<const char*, const char*> units[] = {
      {"/mesh/coordinates", "nm"}, {"/mesh/connectivity", "1"}, {"/mesh/block_id", "1"},
      {"/steps/step_000000/nodal/displacement", "nm"}, {"/steps/step_000000/nodal/temperature", "K"},
      {"/steps/step_000000/element/stress", "Pa"}, {"/steps/step_000000/element/plastic_strain", "1"},
      {"/steps/step_000000/element/slip", "nm"}};
  for (const auto& [path, unit] : units) {
    EXPECT_EQ(read_units(f, path), unit) << path;
    const hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
    const hid_t dcpl = H5Dget_create_plist(d);
    EXPECT_EQ(H5Pget_layout(dcpl), H5D_CHUNKED) << path;
    EXPECT_EQ(H5Pget_nfilters(dcpl), 2) << path;  // shuffle, deflate
    H5Pclose(dcpl);
    H5Dclose(d);
  }
  H5Fclose(f);
  const std::string xml = slurp(dir / "results.xdmf");
  EXPECT_NE(xml.find("<Information Name=\"length_unit\" Value=\"nm\"/>"), std::string::npos);
  EXPECT_NE(xml.find("Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\"><Information Name=\"units\" Value=\"nm\"/>"),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"stress\" AttributeType=\"Tensor\" Center=\"Cell\"><Information Name=\"units\" Value=\"Pa\"/>"),
            std::string::npos);
  // A resumed run keeps the file's unit whatever it is asked for.
  ResultsWriter resumed(dir.string(), mesh, nullptr, 1.0, {"m"});
  EXPECT_EQ(resumed.length_unit(), "nm");
  EXPECT_EQ(resumed.step_count(), 1);
  fs::remove_all(dir);
}
