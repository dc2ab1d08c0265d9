// SPDX-License-Identifier: MIT
// What the partition takes from the contact definition (solver/contact_partition.hpp): the links
// between facing elements, and that the partition keeps linked elements on one rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mesh/box.hpp"
#include "solver/contact_partition.hpp"
#include "solver/parallel/partition.hpp"

using namespace tribex;

namespace {

// A 12 x 12 x 4 block of unit cubes and a 6 x 6 x 2 indenter on the centre of its top face.
mesh::Mesh block_and_indenter() {
  mesh::BoxSpec block, indenter;
  block.name = "block";
  block.size = {12, 12, 4};
  block.intervals = {12, 12, 4};
  indenter.name = "indenter";
  indenter.origin = {3, 3, 4};
  indenter.size = {6, 6, 2};
  indenter.intervals = {6, 6, 2};
  mesh::Mesh m = mesh::generate_box(block);
  mesh::append(m, mesh::generate_box(indenter));
  return m;
}

inputs::ContactSpec indenter_on_block() {
  inputs::ContactSpec spec;
  spec.surfaces.push_back({"tip", {"indenter_zmin"}, {}});
  spec.surfaces.push_back({"top", {"block_zmax"}, {}});
  inputs::InteractionSpec it;
  it.name = "press";
  it.slave = "tip";
  it.master = "top";
  spec.interactions.push_back(it);
  return spec;
}

std::array<double, 3> centroid(const mesh::Mesh& m, int e) {
  std::array<double, 3> c{0, 0, 0};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) c[i] += m.coordinates[3 * static_cast<std::size_t>(m.connectivity[8 * e + a]) + i] / 8;
  return c;
}

}  // namespace

TEST(ContactPartition, LinksJoinTheElementsFacingEachOther) {
  const mesh::Mesh m = block_and_indenter();
  const inputs::ContactSpec spec = indenter_on_block();
  const std::vector<int> links = solver::contact_element_links(m, &spec);
  ASSERT_EQ(links.size() % 2, 0u);
  // Each of the 36 indenter bottom elements is linked to the block element under it; block top elements
  // beside the footprint (within two face diagonals) link to the nearest indenter element too.
  const int first_indenter = 12 * 12 * 4;
  int under = 0;
  for (std::size_t k = 0; k < links.size(); k += 2) {
    const int a = links[k], b = links[k + 1];
    ASSERT_LT(a, b);
    ASSERT_LT(a, first_indenter) << "a link joins the two bodies";
    ASSERT_GE(b, first_indenter);
    const auto ca = centroid(m, a), cb = centroid(m, b);
    EXPECT_NEAR(ca[2], 3.5, 1e-12);  // the block's top layer
    EXPECT_NEAR(cb[2], 4.5, 1e-12);  // the indenter's bottom layer
    EXPECT_LE(std::hypot(ca[0] - cb[0], ca[1] - cb[1]), 2.0 * std::sqrt(2.0) + 1e-12);
    under += ca[0] == cb[0] && ca[1] == cb[1];
  }
  EXPECT_EQ(under, 36);
  // Pairs ascending, each once.
  for (std::size_t k = 2; k < links.size(); k += 2)
    EXPECT_TRUE(links[k - 2] < links[k] || (links[k - 2] == links[k] && links[k - 1] < links[k + 1]));
  EXPECT_TRUE(solver::contact_element_links(m, nullptr).empty());
}

TEST(ContactPartition, LinkedElementsMostlyShareARank) {
  const mesh::Mesh m = block_and_indenter();
  const inputs::ContactSpec spec = indenter_on_block();
  const std::vector<int> links = solver::contact_element_links(m, &spec);
  const auto balanced = solver::contact_surface_elements(m, &spec);
  auto cut = [&](const std::vector<int>& part) {
    int n = 0;
    for (std::size_t k = 0; k < links.size(); k += 2) n += part[links[k]] != part[links[k + 1]];
    return n;
  };
  const int parts = 4;
  const auto without = solver::parallel::partition_elements(m, parts, balanced);
  const auto with = solver::parallel::partition_elements(m, parts, balanced, links);
  const int links_count = static_cast<int>(links.size() / 2);
  std::printf("links %d: cut %d with them in the graph, %d without\n", links_count, cut(with), cut(without));
  EXPECT_LT(cut(with), cut(without));
  EXPECT_LE(cut(with), links_count / 4) << "of " << links_count << " links";
  // Still every part holds its share of the elements and of each surface's elements.
  for (int p = 0; p < parts; ++p) {
    EXPECT_NEAR(std::count(with.begin(), with.end(), p), m.element_count() / parts, 0.05 * m.element_count() / parts);
    for (const auto& set : balanced) {
      int marked = 0, mine = 0;
      for (int e = 0; e < m.element_count(); ++e) {
        marked += set[e] != 0;
        mine += set[e] != 0 && with[e] == p;
      }
      EXPECT_NEAR(mine, marked / parts, 0.1 * marked / parts + 1) << "part " << p;
    }
  }
}
