// SPDX-License-Identifier: MIT
// Exodus II read/write: round trip (64-bit offset and netCDF-4, long names, id maps), files built
// with the Exodus C API the way other tools write them (classic format, unnamed entities, unused
// nodes, a TETRA4 block), and bad files (missing, garbage, truncated).
#include <gtest/gtest.h>
#include <exodusII.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "mesh/box.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/mesh_error.hpp"
#include "tests/mesh/support.hpp"
#include "tests/support/mesh_part_equal.hpp"

namespace tribex::mesh {
namespace {

namespace fs = std::filesystem;

using ExodusIo = ScratchDirTest;

std::string read_error(const std::string& path) {
  try {
    read_exodus(path);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

// two_boxes() plus a long-named node set and side set.
Mesh two_block_mesh() {
  Mesh m = two_boxes();
  m.node_sets["a_node_set_with_a_name_longer_than_thirty_two_characters"] = {0, 3, 7};
  m.side_sets["a_side_set_with_a_name_longer_than_thirty_two_characters"] = {{1, 5}, {0, 4}};
  return m;
}

void expect_same(const Mesh& a, const Mesh& b) {
  // Reading adds a side set's nodes as the node set of its name where the file has none (as gmsh's).
  Mesh expected = a;
  for (const auto& [name, sides] : a.side_sets)
    if (!expected.node_sets.count(name)) expected.node_sets[name] = a.side_set_nodes(name);
  test::expect_same_mesh(b, expected);  // coordinates bit for bit
}

TEST_F(ExodusIo, RoundTripKeepsEverything) {
  const Mesh m = two_block_mesh();
  for (const char* name : {"mesh.exo", "mesh.g", "mesh.e", "MESH.GEN"}) {
    write_exodus(m, file(name));
    expect_same(m, read_exodus(file(name)));
  }
  EXPECT_EQ(read_exodus(file("mesh.exo")).node_sets.at("a_side_set_with_a_name_longer_than_thirty_two_characters"),
            m.side_set_nodes("a_side_set_with_a_name_longer_than_thirty_two_characters"));
  EXPECT_FALSE(fs::exists(file(".mesh.exo.partial")));
  // 64-bit offset netCDF: "CDF\2".
  std::ifstream in(file("mesh.exo"), std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), std::string("CDF\x02", 4));
}

TEST_F(ExodusIo, NetCdf4RoundTrip) {
  // netCDF-4 files (HDF5 inside, as Cubit may write) read through the same Open MPI HDF5 tribex uses.
  const Mesh m = two_block_mesh();
  write_exodus(m, file("mesh4.exo"), ExodusFormat::netcdf4);
  std::ifstream in(file("mesh4.exo"), std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "HDF");
  expect_same(m, read_exodus(file("mesh4.exo")));
}

TEST_F(ExodusIo, IdMapsDoNotChangeTheTopology) {
  // Connectivity and sets refer to positions (Exodus's internal numbering); the id maps only
  // rename nodes and elements for the user.
  const Mesh m = two_block_mesh();
  write_exodus(m, file("mapped.exo"));
  int comp = 8, io = 0;
  float version = 0;
  const int exo = ex_open(file("mapped.exo").c_str(), EX_WRITE, &comp, &io, &version);
  ASSERT_GE(exo, 0);
  std::vector<int> node_ids(static_cast<std::size_t>(m.node_count())), element_ids(static_cast<std::size_t>(m.element_count()));
  for (std::size_t i = 0; i < node_ids.size(); ++i) node_ids[i] = 1000 + 7 * static_cast<int>(node_ids.size() - i);
  for (std::size_t i = 0; i < element_ids.size(); ++i) element_ids[i] = 50000 + 3 * static_cast<int>(i);
  ASSERT_GE(ex_put_id_map(exo, EX_NODE_MAP, node_ids.data()), 0);
  ASSERT_GE(ex_put_id_map(exo, EX_ELEM_MAP, element_ids.data()), 0);
  ex_close(exo);
  expect_same(m, read_exodus(file("mapped.exo")));
}

// A one-hex file (plus `extra_nodes` nodes no element uses) written the way other tools do:
// no names, block id 10, node set id 3, side set id 7; `type` and `nodes_per` set the block.
void write_raw(const std::string& path, int mode, const char* type, int nodes_per, int extra_nodes = 0) {
  int comp = 8, io = 8;
  const int exo = ex_create(path.c_str(), EX_CLOBBER | mode, &comp, &io);
  ASSERT_GE(exo, 0);
  const int n = 8 + extra_nodes;
  ASSERT_GE(ex_put_init(exo, "raw", 3, n, 1, 1, 1, 1), 0);
  std::vector<double> x(n), y(n), z(n);
  const int s[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  // The extra nodes come first, so the hex's nodes are renumbered on reading.
  for (int i = 0; i < n; ++i) {
    const int a = i - extra_nodes;
    x[i] = a >= 0 ? s[a][0] : 5.0 + i;
    y[i] = a >= 0 ? s[a][1] : 0.0;
    z[i] = a >= 0 ? s[a][2] : 0.0;
  }
  ASSERT_GE(ex_put_coord(exo, x.data(), y.data(), z.data()), 0);
  ASSERT_GE(ex_put_block(exo, EX_ELEM_BLOCK, 10, type, 1, nodes_per, 0, 0, 0), 0);
  std::vector<int> conn(static_cast<std::size_t>(nodes_per));
  for (int a = 0; a < nodes_per; ++a) conn[a] = a + 1 + extra_nodes;
  ASSERT_GE(ex_put_conn(exo, EX_ELEM_BLOCK, 10, conn.data(), nullptr, nullptr), 0);
  const int ns[4] = {1 + extra_nodes, 2 + extra_nodes, 3 + extra_nodes, 4 + extra_nodes};
  ASSERT_GE(ex_put_set_param(exo, EX_NODE_SET, 3, 4, 0), 0);
  ASSERT_GE(ex_put_set(exo, EX_NODE_SET, 3, ns, nullptr), 0);
  const int elems[1] = {1}, sides[1] = {5};
  ASSERT_GE(ex_put_set_param(exo, EX_SIDE_SET, 7, 1, 0), 0);
  ASSERT_GE(ex_put_set(exo, EX_SIDE_SET, 7, elems, sides), 0);
  ex_close(exo);
}

TEST_F(ExodusIo, ClassicFileWithoutNamesGetsSierraNames) {
  write_raw(file("classic.g"), EX_NORMAL_MODEL, "HEX8", 8, 2);
  std::ifstream in(file("classic.g"), std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), std::string("CDF\x01", 4));  // classic netCDF
  const Mesh m = read_exodus(file("classic.g"));
  EXPECT_EQ(m.node_count(), 8);  // the 2 nodes no hex uses are dropped
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "block_10");
  EXPECT_EQ(m.node_sets.at("nodelist_3"), (std::vector<int>{0, 1, 2, 3}));
  ASSERT_EQ(m.side_sets.at("surface_7").size(), 1u);
  EXPECT_EQ(m.side_sets.at("surface_7")[0], (Side{0, 4}));  // Exodus side 5 = face 4, zeta = -1
  EXPECT_EQ(m.coordinates[3 * 6], 1.0);                    // node 7 of the hex: (1, 1, 1)
  EXPECT_EQ(m.connectivity, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST_F(ExodusIo, HexTypeNamesAreAccepted) {
  for (const char* type : {"HEX", "hex8", "HEXAHEDRON"}) {
    write_raw(file("t.exo"), EX_LARGE_MODEL, type, 8);
    EXPECT_EQ(read_exodus(file("t.exo")).element_count(), 1) << type;
  }
}

TEST_F(ExodusIo, NonHexBlockIsRefusedNamingFileAndBlock) {
  write_raw(file("tets.exo"), EX_LARGE_MODEL, "TETRA4", 4);
  const std::string e = read_error(file("tets.exo"));
  EXPECT_NE(e.find(file("tets.exo") + ": element block 'block_10' (id 10) has 1 TETRA4 elements"), std::string::npos) << e;
  EXPECT_NE(e.find("HEX8 only"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  write_raw(file("hex20.exo"), EX_LARGE_MODEL, "HEX20", 20);
  EXPECT_NE(read_error(file("hex20.exo")).find("HEX20 elements with 20 nodes"), std::string::npos);
}

TEST_F(ExodusIo, BadFilesGiveOneLineNamingTheFile) {
  EXPECT_NE(read_error(file("missing.exo")).find(file("missing.exo") + ": no such file"), std::string::npos);
  std::ofstream(file("garbage.exo")) << "this is not a netCDF file\n";
  const std::string g = read_error(file("garbage.exo"));
  EXPECT_NE(g.find(file("garbage.exo") + ": not an Exodus II file"), std::string::npos) << g;
  // A real file cut in half: netCDF's signature is there, the data is not.
  write_exodus(two_block_mesh(), file("whole.exo"));
  std::ifstream in(file("whole.exo"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(file("cut.exo"), std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  const std::string c = read_error(file("cut.exo"));
  EXPECT_NE(c.find(file("cut.exo") + ": "), std::string::npos) << c;
  EXPECT_EQ(c.find('\n'), std::string::npos) << c;
}

TEST_F(ExodusIo, WriteRefusesAnInvalidMeshAndLeavesNothing) {
  Mesh m = two_block_mesh();
  m.connectivity[3] = 100000;
  EXPECT_THROW(write_exodus(m, file("bad.exo")), MeshError);
  EXPECT_FALSE(fs::exists(file("bad.exo")));
  EXPECT_FALSE(fs::exists(file(".bad.exo.partial")));
}

TEST_F(ExodusIo, ExtensionsThatMeanExodus) {
  for (const char* p : {"a.exo", "b/c.g", "d.E", "e.gen", "f.EXO"}) EXPECT_TRUE(is_exodus_path(p)) << p;
  for (const char* p : {"a.msh", "b.exodus", "g", "x.h5"}) EXPECT_FALSE(is_exodus_path(p)) << p;
}

}  // namespace
}  // namespace tribex::mesh
