// SPDX-License-Identifier: MIT
// A gmsh MSH 4.1 file read in slices (mesh/msh_slices.hpp through solver/parallel/file_slice_source.hpp,
// `set-up = distributed`), run under mpiexec at 1, 2 and 4 ranks (tests/parallel_unit/CMakeLists.txt).
// Rank 0 writes the file (write_gmsh: blocks as physical volumes, side sets as physical surfaces of quads,
// the node sets that are not a side set's as physical points); every rank reads it whole as well (read_gmsh:
// the serial reference, small here) and checks that the part it builds from its slices alone (source_part)
// is split_mesh's part of the serial mesh under the same partition: the same global element and node
// numbers, bitwise the same coordinates, the same connectivity, blocks, node sets (a physical surface's
// nodes made one, as read_gmsh does) and side sets (quads matched to hex faces) in the set's order, the same
// holders and whole-mesh set sizes. ASCII and binary files; the slabs and a scattered partition. Also: the
// streamed SHA-256 is the serial mesh's, and a truncated file is a one-line MeshError naming a byte. Rank 0
// walks the file and the others take its index, as the set-up does. Also files gmsh's own mesher writes (nodes
// in an entity block per point, curve, surface and volume; elements of every dimension), with and without
// physical groups.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "mesh/asperity.hpp"
#include "mesh/box.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/msh_slices.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/element_slab.hpp"
#include "solver/parallel/file_slice_source.hpp"
#include "solver/parallel/mesh_part.hpp"
#include "solver/parallel/source_parts.hpp"
#include "solver/restart/run_fingerprint.hpp"
#include "tests/parallel_unit/mpi/source_part_checks.hpp"
#include "tests/support/gmsh_box.hpp"
#include "tests/support/mpi_hertz_asperity.hpp"

namespace tribex {
namespace {

namespace par = solver::parallel;

// A graded box beside tests/parallel/mpi_hertz.i's asperity: two blocks of hexes, side sets on both bodies.
// The box's 4,320 hexes and 5,168 nodes pass the 4,096 entries between an ASCII block's marks (msh_slices.cpp).
mesh::Mesh box_and_asperity() { return test::box_beside_mpi_hertz_asperity({18, 16, 15}); }

std::string file(const std::string& name) { return "msh_slab_np" + std::to_string(par::size()) + "_" + name; }

// Rank 0 writes `m` to `path`; the others wait for it.
void write(const mesh::Mesh& m, const std::string& path, bool binary) {
  if (par::rank() == 0) mesh::write_gmsh(m, path, binary);
  MPI_Barrier(MPI_COMM_WORLD);
}

// The part of this rank from the slices against split_mesh of the serial mesh, under `part` [element].
void expect_parts(const std::string& path, const std::vector<int>& part, const char* what,
                  const std::vector<std::string>& sets = {"tip_surface", "substrate_top"}) {
  SCOPED_TRACE(std::string(what) + ", " + path + ", " + std::to_string(par::size()) + " ranks, rank " +
               std::to_string(par::rank()));
  const mesh::Mesh whole = mesh::read_gmsh(path);
  // As the set-up does: rank 0 walks the file, the others take its index.
  std::unique_ptr<mesh::MshSlices> slices;
  std::string index;
  if (par::rank() == 0) {
    slices = std::make_unique<mesh::MshSlices>(path);
    index = slices->index();
  }
  par::broadcast(index, 0);
  if (par::rank() != 0) slices = std::make_unique<mesh::MshSlices>(path, index);
  EXPECT_EQ(slices->index(), index);
  ASSERT_EQ(slices->unsupported(), "");
  par::FileSliceSource source(std::move(slices));
  source.route();
  EXPECT_EQ(source.node_count(), whole.node_count());
  test::expect_source_part(source, whole, part, sets);
  EXPECT_EQ(solver::mesh_sha256(mesh::MshSlices(path)), solver::mesh_sha256(whole));
}

void expect_file(const std::string& path, int elements) {
  test::for_slab_and_scattered_partitions(
      elements, [&](const std::vector<int>& part, const char* what) { expect_parts(path, part, what); });
}

TEST(MshSlab, BinaryPartsAreSplitMeshParts) {
  const mesh::Mesh m = box_and_asperity();
  write(m, file("binary.msh"), true);
  // The file holds physical points (node sets that are no side set's nodes): the 0-D path is exercised.
  const mesh::MshSlices slices(file("binary.msh"));
  EXPECT_FALSE(slices.node_sets().names.empty());
  EXPECT_EQ(slices.element_count(), m.element_count());
  expect_file(file("binary.msh"), m.element_count());
}

TEST(MshSlab, AsciiPartsAreSplitMeshParts) {
  const mesh::Mesh m = box_and_asperity();
  write(m, file("ascii.msh"), false);
  expect_file(file("ascii.msh"), m.element_count());
}

// Rank 0 meshes an OCC box 1 x 2 x 0.5 with gmsh (transfinite 6 x 5 x 4 intervals, recombined to hexes) and
// writes it: with a physical volume, the top as a physical surface and a corner as a physical point, or with
// no physical group (every element written; one block "block_1", no sets).
void mesh_box_with_gmsh(const std::string& path, bool binary, bool groups) {
  if (par::rank() == 0) {
    mesh::GmshSession session;
    mesh::GmshScratchModel model("msh slab test");
    test::add_transfinite_gmsh_box({6, 5, 4});
    gmsh::model::mesh::generate(3);
    if (groups) test::add_gmsh_box_groups();
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write(path);
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

TEST(MshSlab, FilesOfGmshsOwnMesher) {
  for (const bool binary : {true, false})
    for (const bool groups : {true, false}) {
      const std::string path = file(std::string("gmsh_") + (binary ? "binary" : "ascii") + (groups ? "" : "_bare") + ".msh");
      mesh_box_with_gmsh(path, binary, groups);
      const mesh::Mesh whole = mesh::read_gmsh(path);
      ASSERT_EQ(whole.element_count(), 6 * 5 * 4) << path;
      EXPECT_EQ(whole.node_sets.count("nodes_7"), groups ? 1u : 0u) << path;
      EXPECT_EQ(whole.side_sets.count("top"), groups ? 1u : 0u) << path;
      const int elements = whole.element_count(), ranks = par::size();
      std::vector<int> scattered(static_cast<std::size_t>(elements));
      for (int e = 0; e < elements; ++e) scattered[static_cast<std::size_t>(e)] = (7 * e + e / 13) % ranks;
      if (!groups) {  // expect_parts asks for tip_surface / substrate_top: only the part here
        par::FileSliceSource source(std::make_unique<mesh::MshSlices>(path));
        source.route();
        test::expect_source_part(source, whole, scattered, {});
        continue;
      }
      expect_parts(path, scattered, "scattered partition", {"top"});
    }
}

// Walking `path` fails with one MeshError line that starts "PATH: byte " and holds `holds`.
void expect_byte_error(const std::string& path, const std::string& holds) {
  try {
    mesh::MshSlices slices(path);
    ADD_FAILURE() << path << ": no error";
  } catch (const mesh::MeshError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path + ": byte ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(holds), std::string::npos) << what;
  }
}

// A corrupt (not cut) ASCII file: the first hex's first node tag made 999999999, outside $Nodes' range.
TEST(MshSlab, CorruptTagIsOneLineNamingAByte) {
  const std::string path = file("corrupt.msh");
  write(box_and_asperity(), path, false);
  if (par::rank() == 0) {
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // $Elements, its header line, the first block's header line, then "tag node ...": the node replaced.
    std::size_t at = text.find("$Elements\n");
    for (int line = 0; line < 3; ++line) at = text.find('\n', at) + 1;
    const std::size_t node = text.find(' ', at) + 1, end = text.find(' ', node);
    text.replace(node, end - node, "999999999");
    std::ofstream(path) << text;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  expect_byte_error(path, "element node tag 999999999 is outside the declared range");
}

TEST(MshSlab, TruncatedFileIsOneLineNamingAByte) {
  const mesh::Mesh m = box_and_asperity();
  for (const bool binary : {true, false}) {
    const std::string path = file(binary ? "cut_binary.msh" : "cut_ascii.msh");
    write(m, path, binary);
    if (par::rank() == 0) std::filesystem::resize_file(path, std::filesystem::file_size(path) * 2 / 3);
    MPI_Barrier(MPI_COMM_WORLD);
    expect_byte_error(path, "");
  }
}

}  // namespace
}  // namespace tribex
