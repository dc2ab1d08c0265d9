// SPDX-License-Identifier: MIT
// The distributed partition (`method = ptscotch`: solver/parallel/face_dual_graph.hpp,
// ptscotch_partition.hpp, element_slabs.hpp), run under mpiexec at 1, 2 and 4 ranks
// (tests/parallel_unit/CMakeLists.txt): every rank builds the same small mesh and takes its slab of it.
//   - the distributed dual graph is the face graph of the whole mesh, row for row (a serial face map as
//     the reference);
//   - PT-Scotch into 4 and 8 parts: every element in exactly one part in [0, parts), every part within
//     5 % of the even share, the edge cut (faces between parts) at most 1.5 x METIS's on the same graph
//     (partition_elements), the same parts on a second call; on a box of 16^3 and the generated
//     asperity of tests/parallel/mpi_hertz.i;
//   - rank 0's partition_elements_ptscotch is the gathered slab partition; more parts than elements
//     throws on every rank; a rank whose slab is empty (3 elements on 4 ranks) takes part.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "mesh/asperity.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/element_slabs.hpp"
#include "solver/parallel/face_dual_graph.hpp"
#include "solver/parallel/partition.hpp"
#include "solver/parallel/ptscotch_partition.hpp"
#include "tests/parallel_unit/cube_mesh.hpp"
#include "tests/support/mpi_hertz_asperity.hpp"

namespace tribex {
namespace {

namespace par = solver::parallel;

// The asperity of tests/parallel/mpi_hertz.i (1.6 nm elements): a tip and a substrate, two bodies.
mesh::Mesh asperity_mesh() { return mesh::generate_asperity(test::mpi_hertz_asperity()); }

// This rank's slab of `whole` under the even split (what scatter_element_slabs sends it).
par::ElementSlab slab_of(const mesh::Mesh& whole) {
  const std::vector<int> offset = par::slab_offsets(whole.element_count(), par::size());
  par::ElementSlab slab;
  slab.first = offset[par::rank()];
  slab.count = offset[par::rank() + 1] - slab.first;
  slab.nodes.assign(whole.connectivity.begin() + 8 * slab.first,
                    whole.connectivity.begin() + 8 * (slab.first + slab.count));
  return slab;
}

// The reference: [element] its face neighbours, ascending, from a serial map of sorted face nodes.
std::vector<std::vector<int>> serial_face_graph(const mesh::Mesh& m) {
  std::map<std::array<int, 4>, std::vector<int>> faces;
  for (int e = 0; e < m.element_count(); ++e)
    for (const auto& face : mesh::hex8_face_nodes) {
      std::array<int, 4> key;
      for (int k = 0; k < 4; ++k) key[k] = m.connectivity[8 * e + face[k]];
      std::sort(key.begin(), key.end());
      faces[key].push_back(e);
    }
  std::vector<std::vector<int>> next(static_cast<std::size_t>(m.element_count()));
  for (const auto& [key, elements] : faces)
    for (int a : elements)
      for (int b : elements)
        if (a != b) next[a].push_back(b);
  for (auto& row : next) std::sort(row.begin(), row.end());
  return next;
}

// Faces whose two elements are in different parts.
long edge_cut(const std::vector<std::vector<int>>& graph, const std::vector<int>& part) {
  long cut = 0;
  for (std::size_t e = 0; e < graph.size(); ++e)
    for (int other : graph[e]) cut += part[e] != part[other];
  return cut / 2;
}

void expect_same_graph(const mesh::Mesh& whole) {
  const par::ElementSlab slab = slab_of(whole);
  const par::DualGraphRows rows = par::face_dual_graph(slab);
  const auto reference = serial_face_graph(whole);
  ASSERT_EQ(rows.vertex_offset, par::slab_offsets(whole.element_count(), par::size()));
  ASSERT_EQ(rows.offset.size(), static_cast<std::size_t>(slab.count) + 1);
  for (int e = 0; e < slab.count; ++e) {
    const std::vector<int> row(rows.neighbour.begin() + rows.offset[e], rows.neighbour.begin() + rows.offset[e + 1]);
    ASSERT_EQ(row, reference[slab.first + e]) << "element " << slab.first + e << " on rank " << par::rank();
  }
}

// PT-Scotch's parts of `whole` against METIS's, checked on rank 0; `name` for the printed figures.
void expect_good_partition(const mesh::Mesh& whole, int parts, const char* name) {
  const par::ElementSlab slab = slab_of(whole);
  const par::DualGraphRows rows = par::face_dual_graph(slab);
  const std::vector<int> mine = par::ptscotch_parts(rows, parts);
  EXPECT_EQ(par::ptscotch_parts(rows, parts), mine) << "the same parts on a second call";
  const std::vector<int> part = par::gather_slab_parts(slab, mine);
  // Rank 0's one-call path gives the same parts as the slabs' (the same graph, the same ranks).
  const std::vector<int> direct = par::partition_elements_ptscotch(par::rank() == 0 ? &whole : nullptr, parts);
  if (par::rank() != 0) return;
  EXPECT_EQ(direct, part);
  const int ne = whole.element_count();
  ASSERT_EQ(part.size(), static_cast<std::size_t>(ne));
  std::vector<int> size(static_cast<std::size_t>(parts), 0);
  for (int p : part) {
    ASSERT_GE(p, 0);
    ASSERT_LT(p, parts);
    ++size[p];
  }
  const double share = double(ne) / parts;
  for (int p = 0; p < parts; ++p) EXPECT_LE(std::abs(size[p] - share), 0.05 * share) << "part " << p << " of " << parts;
  const auto graph = serial_face_graph(whole);
  const long cut = edge_cut(graph, part), metis = edge_cut(graph, par::partition_elements(whole, parts));
  std::printf("%s, %d elements, %d parts on %d ranks: parts %d-%d, edge cut %ld (METIS %ld, ratio %.3f)\n", name, ne,
              parts, par::size(), *std::min_element(size.begin(), size.end()),
              *std::max_element(size.begin(), size.end()), cut, metis, double(cut) / metis);
  EXPECT_LE(cut, 1.5 * metis);
}

TEST(PtScotchPartition, DualGraphIsTheFaceGraph) {
  expect_same_graph(test::cube_mesh(9));
  expect_same_graph(asperity_mesh());
}

TEST(PtScotchPartition, BoxBalancedWithinFivePercentCutWithinOneAndAHalfMetis) {
  const mesh::Mesh box = test::cube_mesh(16);
  for (int parts : {4, 8}) expect_good_partition(box, parts, "box 16^3");
}

TEST(PtScotchPartition, AsperityBalancedWithinFivePercentCutWithinOneAndAHalfMetis) {
  const mesh::Mesh asperity = asperity_mesh();
  for (int parts : {4, 8}) expect_good_partition(asperity, parts, "asperity (mpi_hertz.i)");
}

TEST(PtScotchPartition, OnePartIsAllZerosAndTooManyPartsThrowsOnEveryRank) {
  const mesh::Mesh cube = test::cube_mesh(2);  // 8 elements
  const par::DualGraphRows rows = par::face_dual_graph(slab_of(cube));
  const std::vector<int> one = par::ptscotch_parts(rows, 1);
  EXPECT_TRUE(std::all_of(one.begin(), one.end(), [](int p) { return p == 0; }));
  EXPECT_THROW(par::ptscotch_parts(rows, 9), std::runtime_error);
}

TEST(PtScotchPartition, RanksWithoutElementsTakePart) {
  // 3 elements in a row: at 4 ranks the last slab is empty; its rank still joins every collective.
  mesh::BoxSpec spec;
  spec.intervals = {3, 1, 1};
  const mesh::Mesh row = mesh::generate_box(spec);
  const par::ElementSlab slab = slab_of(row);
  const par::DualGraphRows rows = par::face_dual_graph(slab);
  const std::vector<int> part = par::gather_slab_parts(slab, par::ptscotch_parts(rows, 2));
  if (par::rank() != 0) return;
  ASSERT_EQ(part.size(), 3u);
  EXPECT_NE(part[0], part[2]) << "the two ends in different parts";
  for (int p : part) EXPECT_TRUE(p == 0 || p == 1);
}

}  // namespace
}  // namespace tribex
