// SPDX-License-Identifier: MIT
// gmsh .msh read/write: round trip of a generated mesh, a mesh made by gmsh's own mesher, and bad
// files (missing, not .msh, truncated, tetrahedra, quads that are not hex faces).
#include <gtest/gtest.h>
#include <gmsh.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <unistd.h>

#include "mesh/box.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/mesh_error.hpp"
#include "tests/mesh/support.hpp"
#include "tests/support/gmsh_box.hpp"

namespace tribex::mesh {
namespace {

namespace fs = std::filesystem;

using GmshIo = ScratchDirTest;

std::string read_error(const std::string& path) {
  try {
    read_gmsh(path);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

/// Element volume from the centre Jacobian (exact for parallelepipeds): V = 8 det J(0).
double brick_volume(const Mesh& m, int e) {
  double J[3][3] = {};
  const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) J[k][d] += 0.125 * s[a][k] * m.coordinates[3 * m.connectivity[8 * e + a] + d];
  const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                     J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  return 8.0 * det;
}

/// Outward test for a side: (face centroid - element centroid) . face normal > 0.
bool points_outward(const Mesh& m, const Side& side) {
  const auto q = m.side_nodes(side);
  auto X = [&](int n, int d) { return m.coordinates[3 * n + d]; };
  double fc[3] = {}, ec[3] = {}, d1[3], d2[3];
  for (int d = 0; d < 3; ++d) {
    for (int k = 0; k < 4; ++k) fc[d] += 0.25 * X(q[k], d);
    for (int a = 0; a < 8; ++a) ec[d] += 0.125 * X(m.connectivity[8 * side.element + a], d);
    d1[d] = X(q[2], d) - X(q[0], d);
    d2[d] = X(q[3], d) - X(q[1], d);
  }
  const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  return (fc[0] - ec[0]) * n[0] + (fc[1] - ec[1]) * n[1] + (fc[2] - ec[2]) * n[2] > 0.0;
}

using Conn = std::array<int, 8>;
Conn element(const Mesh& m, int e) {
  Conn c{};
  std::copy_n(m.connectivity.begin() + 8 * e, 8, c.begin());
  return c;
}

Mesh two_block_mesh() {
  Mesh m = two_boxes();
  m.node_sets["pin"] = {0, 7, 33};
  m.node_sets["tip_zmin"].pop_back();  // differs from its side set's nodes: must travel as its own group
  m.side_sets["interior"] = {{5, 5}, {6, 1}};  // faces inside the substrate
  m.side_sets["unused"] = {};                  // empty sets survive the round trip
  // Overlapping side sets (like substrate_track inside substrate_top): a face in two sets.
  const auto& top = m.side_sets.at("substrate_zmax");
  m.side_sets["patch"] = {top[0], top[1], top[5]};
  m.node_sets["pin_too"] = {7, 33, 40};  // shares nodes with `pin`
  m.node_sets["none"] = {};
  return m;
}

TEST_F(GmshIo, RoundTripOfGeneratedMesh) {
  const fs::path file = scratch_dir() / "two_blocks.msh";
  const Mesh in = two_block_mesh();
  write_gmsh(in, file.string());
  const Mesh out = read_gmsh(file.string());

  EXPECT_EQ(out.coordinates, in.coordinates);  // binary .msh: doubles bit for bit
  ASSERT_EQ(out.element_count(), in.element_count());
  ASSERT_EQ(out.blocks.size(), in.blocks.size());
  // Connectivity up to element reordering: the same multiset of hexes per block, and an element map.
  std::map<Conn, int> in_index;
  for (int e = 0; e < in.element_count(); ++e) in_index[element(in, e)] = e;
  std::vector<int> out_to_in(out.element_count());
  for (const Block& ob : out.blocks) {
    const Block* ib = in.find_block(ob.name);
    ASSERT_NE(ib, nullptr) << ob.name;
    EXPECT_EQ(ob.element_count, ib->element_count);
    for (int e = ob.first_element; e < ob.first_element + ob.element_count; ++e) {
      const auto it = in_index.find(element(out, e));
      ASSERT_NE(it, in_index.end()) << "element " << e << " not in the written mesh";
      EXPECT_GE(it->second, ib->first_element);
      EXPECT_LT(it->second, ib->first_element + ib->element_count);
      out_to_in[e] = it->second;
    }
  }
  // Mapping rule: a physical surface also gives the node set of the same name.
  auto expected_node_sets = in.node_sets;
  expected_node_sets["interior"] = in.side_set_nodes("interior");
  expected_node_sets["unused"] = {};
  expected_node_sets["patch"] = in.side_set_nodes("patch");
  EXPECT_EQ(out.node_sets, expected_node_sets);
  ASSERT_EQ(out.side_sets.size(), in.side_sets.size());
  for (const auto& [name, sides] : in.side_sets) {
    ASSERT_TRUE(out.side_sets.count(name)) << name;
    std::vector<std::pair<int, int>> a, b;
    for (const Side& s : sides) a.emplace_back(s.element, s.face);
    for (const Side& s : out.side_sets.at(name)) b.emplace_back(out_to_in[s.element], s.face);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b) << name;
  }
  // Writing again over the same path works (gmsh session re-initialised) and leaves no partial file.
  write_gmsh(out, file.string());
  EXPECT_EQ(read_gmsh(file.string()).coordinates, in.coordinates);
  EXPECT_FALSE(fs::exists(file.parent_path() / ".two_blocks.msh.partial.msh"));
}

/// gmsh holds each element once (`gmsh -check` counts a quad written for two side sets as a duplicate):
/// in the written file no two 2-D or 0-D elements share the same nodes, yet every set reads back whole.
TEST_F(GmshIo, OverlappingSetsAreWrittenWithoutDuplicateElements) {
  const fs::path file = scratch_dir() / "overlap.msh";
  const Mesh in = two_block_mesh();
  write_gmsh(in, file.string());
  {
    GmshSession session;
    GmshScratchModel model("check");
    gmsh::open(file.string());
    for (int dim : {0, 2}) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, dim);
      std::set<std::vector<std::size_t>> seen;
      std::size_t count = 0;
      for (std::size_t t = 0; t < types.size(); ++t) {
        const std::size_t per = tags[t].empty() ? 1 : nodes[t].size() / tags[t].size();
        for (std::size_t e = 0; e < tags[t].size(); ++e) {
          std::vector<std::size_t> key(nodes[t].begin() + e * per, nodes[t].begin() + (e + 1) * per);
          std::sort(key.begin(), key.end());
          seen.insert(key);
          ++count;
        }
      }
      EXPECT_EQ(seen.size(), count) << "duplicate elements of dimension " << dim;
      EXPECT_GT(count, 0u);
    }
  }
  const Mesh out = read_gmsh(file.string());
  EXPECT_EQ(out.side_sets.at("patch").size(), 3u);
  EXPECT_EQ(out.side_sets.at("substrate_zmax").size(), in.side_sets.at("substrate_zmax").size());
  EXPECT_EQ(out.node_sets.at("pin_too"), in.node_sets.at("pin_too"));
  EXPECT_EQ(out.node_sets.at("pin"), in.node_sets.at("pin"));
}

/// gmsh's own mesher: OCC box 1 x 2 x 0.5, transfinite 3 x 4 x 2 intervals, recombined to hexes.
void mesh_box_with_gmsh(const std::string& path, bool hexes, bool msh2 = false, int order = 1, bool groups = true) {
  GmshSession session;
  GmshScratchModel model("test");
  if (hexes) {
    test::add_transfinite_gmsh_box({3, 4, 2});
  } else {
    gmsh::model::occ::addBox(0, 0, 0, 1.0, 2.0, 0.5);
    gmsh::model::occ::synchronize();
  }
  gmsh::model::mesh::generate(3);
  if (order > 1) gmsh::model::mesh::setOrder(order);
  if (!groups) {
    gmsh::write(path);
    return;
  }
  test::add_gmsh_box_groups();  // the corner's group is unnamed: it becomes "nodes_7"
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::option::setNumber("Mesh.MshFileVersion", msh2 ? 2.2 : 4.1);
  gmsh::write(path);
}

void check_gmsh_made_box(const Mesh& m) {
  EXPECT_EQ(m.element_count(), 3 * 4 * 2);
  EXPECT_EQ(m.node_count(), 4 * 5 * 3);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "solid");
  double volume = 0.0;
  for (int e = 0; e < m.element_count(); ++e) {
    // gmsh's hex order = ours: positive Jacobians; the transfinite bricks are undistorted.
    EXPECT_NEAR(scaled_jacobian(m, e), 1.0, 1e-12) << "element " << e;
    volume += brick_volume(m, e);
  }
  EXPECT_NEAR(volume, 1.0, 1e-12);
  ASSERT_TRUE(m.side_sets.count("top"));
  EXPECT_EQ(m.side_sets.at("top").size(), 12u);
  for (const Side& s : m.side_sets.at("top")) {
    EXPECT_TRUE(points_outward(m, s));
    for (int n : m.side_nodes(s)) EXPECT_DOUBLE_EQ(m.coordinates[3 * n + 2], 0.5);
  }
  EXPECT_EQ(m.node_sets.at("top").size(), 20u);
  ASSERT_TRUE(m.node_sets.count("nodes_7"));
  ASSERT_EQ(m.node_sets.at("nodes_7").size(), 1u);
  const int c = m.node_sets.at("nodes_7")[0];
  EXPECT_EQ(m.coordinates[3 * c] + m.coordinates[3 * c + 1] + m.coordinates[3 * c + 2], 0.0);
}

TEST_F(GmshIo, ReadsTransfiniteHexMeshMadeByGmsh) {
  const fs::path dir = scratch_dir();
  mesh_box_with_gmsh((dir / "box41.msh").string(), true);
  check_gmsh_made_box(read_gmsh((dir / "box41.msh").string()));
  mesh_box_with_gmsh((dir / "box22.msh").string(), true, /*msh2=*/true);
  check_gmsh_made_box(read_gmsh((dir / "box22.msh").string()));
}

TEST_F(GmshIo, ReadInsideAnOpenGmshSessionLeavesItUsable) {
  const fs::path dir = scratch_dir();
  mesh_box_with_gmsh((dir / "box.msh").string(), true);
  GmshSession session;
  GmshScratchModel model("outer");
  gmsh::model::occ::addPoint(1, 2, 3);
  gmsh::model::occ::synchronize();
  EXPECT_EQ(read_gmsh((dir / "box.msh").string()).element_count(), 24);
  gmsh::vectorpair points;
  gmsh::model::getEntities(points, 0);
  EXPECT_EQ(points.size(), 1u);  // the caller's model is current again and intact
}

TEST_F(GmshIo, TetMeshIsRejectedWithTheFix) {
  const fs::path file = scratch_dir() / "tets.msh";
  mesh_box_with_gmsh(file.string(), false);
  const std::string msg = read_error(file.string());
  EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("Tetrahedron"), std::string::npos) << msg;
  EXPECT_NE(msg.find("all-hex8"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Recombine"), std::string::npos) << msg;
}

TEST_F(GmshIo, FileWithoutPhysicalGroupsIsOneBlock) {
  const fs::path file = scratch_dir() / "plain.msh";
  mesh_box_with_gmsh(file.string(), true, false, 1, /*groups=*/false);
  const Mesh m = read_gmsh(file.string());
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "block_1");
  EXPECT_EQ(m.element_count(), 24);
  EXPECT_TRUE(m.side_sets.empty());
}

TEST_F(GmshIo, SecondOrderHexesAreRejected) {
  const fs::path file = scratch_dir() / "hex27.msh";
  mesh_box_with_gmsh(file.string(), true, false, /*order=*/2);
  const std::string msg = read_error(file.string());
  EXPECT_NE(msg.find("Hexahedron 27"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Mesh.ElementOrder = 1"), std::string::npos) << msg;
}

TEST_F(GmshIo, MissingFile) {
  const std::string path = (scratch_dir() / "nope.msh").string();
  const std::string msg = read_error(path);
  EXPECT_EQ(msg.rfind(path + ":", 0), 0u) << msg;
  EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;
}

TEST_F(GmshIo, TextFileThatIsNotMsh) {
  const fs::path file = scratch_dir() / "notes.msh";
  std::ofstream(file) << "hello, this is not a mesh\n";
  const std::string msg = read_error(file.string());
  EXPECT_NE(msg.find(file.string() + ":1:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("$MeshFormat"), std::string::npos) << msg;
}

TEST_F(GmshIo, TruncatedFiles) {
  const fs::path dir = scratch_dir();
  write_gmsh(two_block_mesh(), (dir / "full.msh").string());
  mesh_box_with_gmsh((dir / "ascii.msh").string(), true);
  for (const std::string name : {"full.msh", "ascii.msh"}) {
    std::ifstream in(dir / name, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (double fraction : {0.3, 0.6, 0.9}) {
      const fs::path cut = dir / ("cut_" + std::to_string(int(fraction * 10)) + "_" + name);
      std::ofstream(cut, std::ios::binary) << bytes.substr(0, static_cast<std::size_t>(bytes.size() * fraction));
      const std::string msg = read_error(cut.string());
      EXPECT_NE(msg.find(cut.string()), std::string::npos) << "no MeshError naming the file for " << cut << ": " << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
}

// gmsh 4.8 trusts tags and counts: a huge node tag made it segfault and a huge entity count made it
// spin for minutes in random-corruption trials. The MSH 4.1 pre-scan must turn both into MeshError.
TEST_F(GmshIo, CorruptTagsAndCountsAreCaughtBeforeGmsh) {
  const fs::path good = scratch_dir() / "good.msh";
  write_gmsh(two_block_mesh(), good.string());
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto corrupt = [&](const std::string& name, const std::string& section, std::size_t offset, std::uint64_t value) {
    std::string b = bytes;
    const std::size_t at = b.find("\n$" + section + "\n") + section.size() + 3 + offset;
    std::memcpy(b.data() + at, &value, sizeof value);
    const fs::path file = scratch_dir() / name;
    std::ofstream(file, std::ios::binary) << b;
    return read_error(file.string());
  };
  // $Elements header is 4 size_t; a block header is 3 int + 1 size_t; then tag, node tags.
  std::string msg = corrupt("node_tag.msh", "Elements", 32 + 20 + 8, std::uint64_t(1) << 40);
  EXPECT_NE(msg.find("node_tag.msh: byte "), std::string::npos) << msg;
  EXPECT_NE(msg.find("element node tag 1099511627776 is outside the declared range"), std::string::npos) << msg;
  msg = corrupt("element_tag.msh", "Elements", 32 + 20, std::uint64_t(1) << 56);
  EXPECT_NE(msg.find("element tag"), std::string::npos) << msg;
  msg = corrupt("entities.msh", "Entities", 0, std::uint64_t(1) << 40);
  EXPECT_NE(msg.find("entities.msh: byte "), std::string::npos) << msg;
}

TEST_F(GmshIo, QuadThatIsNoHexFaceIsRejected) {
  const fs::path file = scratch_dir() / "diagonal.msh";
  {
    GmshSession session;
    GmshScratchModel model("bad");
    gmsh::model::addDiscreteEntity(3, 1);
    gmsh::model::addDiscreteEntity(2, 1);
    gmsh::model::mesh::addNodes(3, 1, {1, 2, 3, 4, 5, 6, 7, 8},
                                {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1});
    gmsh::model::mesh::addElementsByType(1, 5, {1}, {1, 2, 3, 4, 5, 6, 7, 8});
    gmsh::model::mesh::addElementsByType(1, 3, {2}, {1, 2, 7, 8});  // a diagonal plane, not a face
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "cube");
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {1}), "cut");
    gmsh::write(file.string());
  }
  const std::string msg = read_error(file.string());
  EXPECT_NE(msg.find("physical surface 'cut' is not a face of any hex"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tribex::mesh
