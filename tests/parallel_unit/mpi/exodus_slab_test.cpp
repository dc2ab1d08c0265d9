// SPDX-License-Identifier: MIT
// An Exodus II file read in slices (solver/parallel/file_slice_source.hpp, `set-up = distributed`), run under
// mpiexec at 1, 2 and 4 ranks (tests/parallel_unit/CMakeLists.txt). Rank 0 writes the file; every rank reads
// it whole as well (read_exodus: the serial reference, small here) and checks that the part it builds from
// its slices alone (source_part) is distribute_mesh's part of the serial mesh under the same partition
// (split_mesh with node_holders): the same global element and node numbers, bitwise the same coordinates,
// the same connectivity, blocks, node sets (a side set without a node set of its name made one, as
// read_exodus does) and side sets in the set's order, the same holders and whole-mesh set sizes. Two
// partitions: the slabs themselves and a scattered one (every rank's part drawn from every slab). Files:
// the asperity of tests/parallel/mpi_hertz.i beside a graded box (two side sets left without their node
// set), written in metres; the same in nanometres (the info record's unit divided out: the same doubles);
// the same as netCDF-4. Also: the streamed SHA-256 is the serial mesh's, the surfaces' elements are the
// side sets', and a file with nodes no element uses gives read_exodus's mesh (those dropped, the others
// renumbered; one of them in a node set).
#include <gtest/gtest.h>
#include <mpi.h>
#include <exodusII.h>

#include <algorithm>
#include <string>
#include <vector>

#include "mesh/asperity.hpp"
#include "mesh/box.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/mesh_error.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/element_slab.hpp"
#include "solver/parallel/file_slice_source.hpp"
#include "solver/parallel/mesh_part.hpp"
#include "solver/parallel/source_parts.hpp"
#include "solver/restart/run_fingerprint.hpp"
#include "tests/parallel_unit/mpi/source_part_checks.hpp"
#include "tests/support/mpi_hertz_asperity.hpp"

namespace tribex {
namespace {

namespace par = solver::parallel;

mesh::Mesh box_and_asperity() {
  mesh::Mesh m = test::box_beside_mpi_hertz_asperity({7, 5, 4});
  // Side sets with no node set of their name: read_exodus makes them node sets (so must the slices).
  m.node_sets.erase("tip_surface");
  m.node_sets.erase("block_zmax");
  return m;
}

// Rank 0 writes `m` to `path` (in `unit`, netCDF `format`); the others wait for it.
void write(const mesh::Mesh& m, const std::string& path, const mesh::ExodusLengthUnit& unit,
           mesh::ExodusFormat format = mesh::ExodusFormat::offset64) {
  if (par::rank() == 0) {
    if (unit.name == "m") {
      mesh::write_exodus(m, path, format);
    } else {
      const int exo = mesh::exodus::create_with_mesh(m, path, "exodus slab test", format, unit);
      ex_close(exo);
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

// The part of this rank from the slices against split_mesh of the serial mesh, under `part` [element].
void expect_parts(const std::string& path, const std::vector<int>& part, const char* what) {
  SCOPED_TRACE(std::string(what) + ", " + path + ", " + std::to_string(par::size()) + " ranks, rank " +
               std::to_string(par::rank()));
  const mesh::Mesh whole = mesh::read_exodus(path);
  par::FileSliceSource source(path);
  source.route();
  test::expect_source_part(source, whole, part, {"tip_surface", "substrate_top"});
  // The streamed hash is the serial mesh's; the file was closed after this rank's reads.
  EXPECT_EQ(solver::mesh_sha256(mesh::ExodusSlices(path)), solver::mesh_sha256(whole));
  EXPECT_THROW(source.file().coordinates(0, 1), mesh::MeshError);
}

void expect_file(const std::string& path, int elements) {
  test::for_slab_and_scattered_partitions(
      elements, [&](const std::vector<int>& part, const char* what) { expect_parts(path, part, what); });
}

std::string file(const std::string& name) { return "exodus_slab_np" + std::to_string(par::size()) + "_" + name; }

TEST(ExodusSlab, PartsAreDistributeMeshParts) {
  const mesh::Mesh m = box_and_asperity();
  write(m, file("m.exo"), {});
  expect_file(file("m.exo"), m.element_count());
}

TEST(ExodusSlab, NanometreFileGivesTheSameDoubles) {
  const mesh::Mesh m = box_and_asperity();
  write(m, file("nm.exo"), {"nm", 1e9});
  expect_file(file("nm.exo"), m.element_count());
}

TEST(ExodusSlab, NetCdf4File) {
  const mesh::Mesh m = box_and_asperity();
  write(m, file("nc4.exo"), {}, mesh::ExodusFormat::netcdf4);
  expect_file(file("nc4.exo"), m.element_count());
}

// `m` with a node no element uses inserted before every 97th node (and at the end), one of them in a node set:
// read_exodus drops them and renumbers the others, so must the slices.
mesh::Mesh with_unused_nodes(const mesh::Mesh& m) {
  mesh::Mesh out = m;
  std::vector<int> new_of(static_cast<std::size_t>(m.node_count()));
  out.coordinates.clear();
  for (int n = 0; n < m.node_count(); ++n) {
    if (n % 97 == 5) out.coordinates.insert(out.coordinates.end(), {-1e-6, -1e-6, static_cast<double>(n) * 1e-9});
    new_of[static_cast<std::size_t>(n)] = out.node_count();
    out.coordinates.insert(out.coordinates.end(), m.coordinates.begin() + 3 * n, m.coordinates.begin() + 3 * n + 3);
  }
  out.coordinates.insert(out.coordinates.end(), {1e-6, 1e-6, 1e-6});
  for (int& n : out.connectivity) n = new_of[static_cast<std::size_t>(n)];
  for (auto& [name, nodes] : out.node_sets)
    for (int& n : nodes) n = new_of[static_cast<std::size_t>(n)];
  auto& set = out.node_sets.at("substrate_bottom");
  set.insert(set.begin(), new_of[5] - 1);  // the first unused node
  return out;
}

TEST(ExodusSlab, UnusedNodesAreDroppedAsReadExodusDoes) {
  const mesh::Mesh m = with_unused_nodes(box_and_asperity());
  write(m, file("unused.exo"), {});
  const mesh::Mesh whole = mesh::read_exodus(file("unused.exo"));
  ASSERT_LT(whole.node_count(), m.node_count());
  par::FileSliceSource source(file("unused.exo"));
  source.route();
  EXPECT_EQ(source.unused_nodes(), m.node_count() - whole.node_count());
  EXPECT_EQ(source.node_count(), whole.node_count());
  expect_file(file("unused.exo"), m.element_count());
}

}  // namespace
}  // namespace tribex
