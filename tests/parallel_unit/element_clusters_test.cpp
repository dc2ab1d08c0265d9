// SPDX-License-Identifier: MIT
// The cluster graph a large mesh is partitioned on (solver/parallel/element_clusters.hpp) and the
// partition computed on it (partition_elements with cluster_size > 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "mesh/box.hpp"
#include "cube_mesh.hpp"
#include "solver/parallel/element_clusters.hpp"
#include "solver/parallel/partition.hpp"

using namespace tribex;
using tribex::test::cube_mesh;

namespace {

// Nodes held by more than one part.
int boundary_nodes(const mesh::Mesh& m, const std::vector<int>& part) {
  std::vector<std::set<int>> holders(static_cast<std::size_t>(m.node_count()));
  for (int e = 0; e < m.element_count(); ++e)
    for (int a = 0; a < 8; ++a) holders[m.connectivity[8 * e + a]].insert(part[e]);
  return static_cast<int>(std::count_if(holders.begin(), holders.end(), [](const auto& h) { return h.size() > 1; }));
}

}  // namespace

TEST(ElementClusters, KdLeavesOfACubeAreCubesAndTheGraphIsSymmetric) {
  const mesh::Mesh m = cube_mesh(8);
  const auto c = solver::parallel::cluster_elements(m, 8);
  ASSERT_EQ(c.count, 64);
  // Each leaf: 8 elements forming a 2 x 2 x 2 cube (element (i,j,k) = i + 8 (j + 8 k)).
  std::map<int, std::vector<int>> members;
  for (int e = 0; e < m.element_count(); ++e) members[c.of_element[e]].push_back(e);
  for (const auto& [cluster, elements] : members) {
    ASSERT_EQ(elements.size(), 8u) << "cluster " << cluster;
    int lo[3] = {8, 8, 8}, hi[3] = {-1, -1, -1};
    for (int e : elements) {
      const int ijk[3] = {e % 8, (e / 8) % 8, e / 64};
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], ijk[i]);
        hi[i] = std::max(hi[i], ijk[i]);
      }
    }
    for (int i = 0; i < 3; ++i) EXPECT_EQ(hi[i] - lo[i], 1) << "cluster " << cluster;
  }
  // Symmetric, no self loops, no repeated neighbour; an interior cluster is a neighbour of the six
  // clusters it shares a face with (of those it touches only along an edge or at a corner, some are
  // missed: a third cluster reached the nodes first).
  ASSERT_EQ(c.offset.size(), 65u);
  std::map<std::pair<int, int>, int> weight;
  for (int a = 0; a < c.count; ++a) {
    std::set<int> seen;
    for (int j = c.offset[a]; j < c.offset[a + 1]; ++j) {
      EXPECT_NE(c.neighbour[j], a);
      EXPECT_TRUE(seen.insert(c.neighbour[j]).second);
      EXPECT_GT(c.weight[j], 0);
      weight[{a, c.neighbour[j]}] = c.weight[j];
    }
  }
  for (const auto& [edge, w] : weight) EXPECT_EQ(weight.at({edge.second, edge.first}), w);
  auto leaf = [&](int i, int j, int k) { return c.of_element[i + 8 * (j + 8 * k)]; };
  const int interior = leaf(2, 2, 2);  // elements 2-3 on each axis
  const int faces[6] = {leaf(0, 2, 2), leaf(4, 2, 2), leaf(2, 0, 2), leaf(2, 4, 2), leaf(2, 2, 0), leaf(2, 2, 4)};
  for (int f : faces) EXPECT_GE(weight.count({interior, f}), 1u) << "face neighbour " << f;
  const int degree = c.offset[interior + 1] - c.offset[interior];
  EXPECT_GE(degree, 6);
  EXPECT_LE(degree, 26);
  // Deterministic.
  EXPECT_EQ(solver::parallel::cluster_elements(m, 8).of_element, c.of_element);
}

TEST(ElementClusters, PartitionOnClustersIsBalancedAndNearTheElementGraphs) {
  const mesh::Mesh m = cube_mesh(16);
  for (int parts : {2, 4, 8}) {
    const auto clustered = solver::parallel::partition_elements(m, parts, 8);
    const auto elements = solver::parallel::partition_elements(m, parts);
    EXPECT_EQ(clustered, solver::parallel::partition_elements(m, parts, 8)) << "repeatable";
    for (int p = 0; p < parts; ++p) {
      const double share = double(std::count(clustered.begin(), clustered.end(), p)) / m.element_count();
      // METIS's 3 % tolerance, at the granularity of a cluster (8 of 4,096 elements).
      EXPECT_NEAR(share, 1.0 / parts, 0.031 / parts + 8.0 / m.element_count()) << parts << " parts, part " << p;
    }
    const int on_clusters = boundary_nodes(m, clustered), on_elements = boundary_nodes(m, elements);
    std::printf("%d parts: %d partition boundary nodes on clusters, %d on the element graph\n", parts, on_clusters, on_elements);
    EXPECT_LE(on_clusters, 1.3 * on_elements) << parts << " parts";
  }
}
