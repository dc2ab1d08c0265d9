// SPDX-License-Identifier: MIT
// Where the contact zone goes in the partition (solver/parallel/contact_partition.hpp): the links between
// facing elements, and the compact patches of the slave surface with their master faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mesh/box.hpp"
#include "solver/parallel/contact_partition.hpp"
#include "solver/setup/contact_setup.hpp"
#include "solver/parallel/partition.hpp"
#include "tests/solver/support.hpp"

using namespace tribex;

namespace {

// A 12 x 12 x 4 block of unit cubes and a 6 x 6 x `height` indenter of unit cubes on its top face, from
// x = indenter_x (default: on the centre).
constexpr int kBlockElements = 12 * 12 * 4;

mesh::Mesh block_and_indenter(double indenter_x = 3, int height = 2) {
  mesh::BoxSpec block, indenter;
  block.name = "block";
  block.size = {12, 12, 4};
  block.intervals = {12, 12, 4};
  indenter.name = "indenter";
  indenter.origin = {indenter_x, 3, 4};
  indenter.size = {6, 6, static_cast<double>(height)};
  indenter.intervals = {6, 6, height};
  mesh::Mesh m = mesh::generate_box(block);
  mesh::append(m, mesh::generate_box(indenter));
  return m;
}

inputs::ContactSpec indenter_on_block() { return test::one_contact("tip", "indenter_zmin", "top", "block_zmax"); }

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
  // (slave, master): each of the 36 indenter bottom elements is linked to the block element under it;
  // block top elements beside the footprint (within two face diagonals) to the nearest indenter element.
  int under = 0;
  for (std::size_t k = 0; k < links.size(); k += 2) {
    const int s = links[k], mst = links[k + 1];
    ASSERT_GE(s, kBlockElements) << "the slave side is the indenter";
    ASSERT_LT(mst, kBlockElements) << "the master side is the block";
    const auto cs = centroid(m, s), cm = centroid(m, mst);
    EXPECT_NEAR(cs[2], 4.5, 1e-12);  // the indenter's bottom layer
    EXPECT_NEAR(cm[2], 3.5, 1e-12);  // the block's top layer
    EXPECT_LE(std::hypot(cs[0] - cm[0], cs[1] - cm[1]), 2.0 * std::sqrt(2.0) + 1e-12);
    under += cs[0] == cm[0] && cs[1] == cm[1];
    if (k > 0) {
      EXPECT_TRUE(links[k - 2] < s || (links[k - 2] == s && links[k - 1] < mst)) << "pairs ascending, once";
    }
  }
  EXPECT_EQ(under, 36);
  EXPECT_TRUE(solver::contact_element_links(m, nullptr).empty());
}

TEST(ContactPartition, PatchesShareTheZoneCompactlyWithTheirMasterFaces) {
  const mesh::Mesh m = block_and_indenter();
  const inputs::ContactSpec spec = indenter_on_block();
  const int parts = 4;
  std::vector<int> part = solver::parallel::partition_elements(m, parts);
  const std::vector<int> metis = part;
  solver::place_contact_patches(m, &spec, parts, part);
  // The 36 slave elements: 9 per part, each part's a 3 x 3 square (a quadrant of the 6 x 6 footprint).
  std::map<int, std::vector<int>> slave_of;
  for (int e = kBlockElements; e < m.element_count(); ++e)
    if (centroid(m, e)[2] == 4.5) slave_of[part[e]].push_back(e);
  ASSERT_EQ(slave_of.size(), 4u);
  for (const auto& [p, elements] : slave_of) {
    ASSERT_EQ(elements.size(), 9u) << "part " << p;
    double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
    for (int e : elements)
      for (int i = 0; i < 2; ++i) {
        lo[i] = std::min(lo[i], centroid(m, e)[i]);
        hi[i] = std::max(hi[i], centroid(m, e)[i]);
      }
    EXPECT_EQ(hi[0] - lo[0], 2.0) << "part " << p;
    EXPECT_EQ(hi[1] - lo[1], 2.0) << "part " << p;
  }
  // The block element under each slave element is on its part; other elements keep METIS's part.
  const std::vector<int> links = solver::contact_element_links(m, &spec);
  std::vector<char> moved(static_cast<std::size_t>(m.element_count()), 0);
  for (std::size_t k = 0; k < links.size(); k += 2) {
    moved[links[k]] = moved[links[k + 1]] = 1;
    const auto cs = centroid(m, links[k]), cm = centroid(m, links[k + 1]);
    if (cs[0] == cm[0] && cs[1] == cm[1]) {
      EXPECT_EQ(part[links[k]], part[links[k + 1]]);
    }
  }
  for (int e = 0; e < m.element_count(); ++e)
    if (!moved[e]) {
      EXPECT_EQ(part[e], metis[e]) << "element " << e;
    }
  // Deterministic; nothing without contact or with one part.
  std::vector<int> again = metis;
  solver::place_contact_patches(m, &spec, parts, again);
  EXPECT_EQ(again, part);
  again = metis;
  solver::place_contact_patches(m, nullptr, parts, again);
  EXPECT_EQ(again, metis);
}

// The patches go to the surface the run enforces as the slave: build_contact swaps a node-to-face
// penalty pair whose slave is more than twice as stiff as its master (solver/setup/contact_setup.hpp
// runs_swapped), so the partition must place the swapped slave, not the deck's (issue 25: on the AFM
// case (b) the deck's slave, the tip, was placed in patches while the SAM track it swaps to kept
// METIS's parts, and the contact zone sat on whichever rank METIS gave it).
TEST(ContactPartition, PatchesGoToTheSurfaceTheRunEnforcesAsSlave) {
  const mesh::Mesh m = block_and_indenter();
  const inputs::ContactSpec deck = indenter_on_block();  // the deck: indenter (tip) slave on the block (top)
  const solver::ContactFaces faces = solver::contact_faces(m, deck);
  // Mesh blocks in order: block, indenter. P-wave moduli, Pa.
  const std::vector<double> stiff_indenter = {100e9, 250e9}, near_equal = {100e9, 150e9};
  const inputs::ContactSpec swapped = solver::as_enforced(deck, faces, stiff_indenter);
  EXPECT_EQ(swapped.interactions[0].slave, "top");
  EXPECT_EQ(swapped.interactions[0].master, "tip");
  EXPECT_EQ(solver::as_enforced(deck, faces, near_equal).interactions[0].slave, "tip");  // 1.5x: the deck's order
  inputs::ContactSpec mortar = deck;
  mortar.interactions[0].enforcement = inputs::InteractionEnforcement::mortar;
  EXPECT_EQ(solver::as_enforced(mortar, faces, stiff_indenter).interactions[0].slave, "tip");

  // Placed with the enforced order, the block's top layer under and around the indenter is cut into
  // the patches: its 12 x 12 top elements, 36 per part.
  const int parts = 4;
  std::vector<int> part = solver::parallel::partition_elements(m, parts);
  solver::place_contact_patches(m, &swapped, parts, part);
  std::map<int, int> top_of;
  for (int e = 0; e < kBlockElements; ++e)
    if (centroid(m, e)[2] == 3.5) ++top_of[part[e]];
  ASSERT_EQ(top_of.size(), 4u);
  for (const auto& [p, count] : top_of) EXPECT_EQ(count, 36) << "part " << p;
}

// `begin decomposition`, method = rcb: recursive coordinate bisection of the element centroids,
// equal counts, each box's longest side (after the coordinate scale) cut at its median.
TEST(Partition, CoordinateBisectionCutsTheScaledLongestSide) {
  mesh::BoxSpec box;
  box.name = "bar";
  box.size = {8, 4, 2};
  box.intervals = {8, 4, 2};
  const mesh::Mesh m = mesh::generate_box(box);
  auto index = [&](int e, int axis) { return static_cast<int>(std::floor(centroid(m, e)[axis])); };
  // Unit scale: x (8) is longest, then each half is 4 x 4 x 2 and x comes first among equals: four
  // slabs of two x columns.
  const std::vector<int> slabs = solver::parallel::partition_elements_rcb(m, 4);
  for (int e = 0; e < m.element_count(); ++e) EXPECT_EQ(slabs[e], index(e, 0) / 2) << "element " << e;
  // x scaled by 0.01: no cut crosses x; y (4) is cut, then y (2) again before z (2): a part per y row.
  const std::vector<int> rows = solver::parallel::partition_elements_rcb(m, 4, {0.01, 1.0, 1.0});
  for (int e = 0; e < m.element_count(); ++e) EXPECT_EQ(rows[e], index(e, 1)) << "element " << e;
  // Three parts: 64 elements split 21 : 43, then 21 : 22 (counts proportional to the parts).
  const std::vector<int> three = solver::parallel::partition_elements_rcb(m, 3);
  EXPECT_EQ(std::count(three.begin(), three.end(), 0), 21);
  EXPECT_EQ(std::count(three.begin(), three.end(), 1), 21);
  EXPECT_EQ(std::count(three.begin(), three.end(), 2), 22);
  EXPECT_EQ(solver::parallel::partition_elements_rcb(m, 3), three) << "deterministic";
  EXPECT_EQ(solver::parallel::partition_elements_rcb(m, 1), std::vector<int>(64, 0));
  EXPECT_THROW(solver::parallel::partition_elements_rcb(m, 65), std::runtime_error);
}

// The case the scale is for: a contact zone that travels along y (a tip sliding on a track). With
// y's scale small, the volume and the slave patches are both cut by the plane x = 6 through the
// indenter's middle, so the patches move no element and wherever the indenter goes along y, half of
// its footprint is on each rank. With unit scale the block (12 x 12) is cut across y as well.
TEST(Partition, ScaledBisectionKeepsATravellingZoneShared) {
  const mesh::Mesh m = block_and_indenter();
  const inputs::ContactSpec spec = indenter_on_block();
  const solver::parallel::AxisScale along_y{1.0, 0.01, 1.0};
  const std::vector<int> volume = solver::parallel::partition_elements_rcb(m, 2, along_y);
  std::vector<int> part = volume;
  solver::place_contact_patches(m, &spec, 2, part, along_y);
  EXPECT_EQ(part, volume) << "the patches agree with the volume's cut";
  for (int e = 0; e < m.element_count(); ++e) EXPECT_EQ(part[e], centroid(m, e)[0] < 6.0 ? 0 : 1) << "element " << e;
}

// The patches are cut through the smaller surface's footprint, where the contact zone is: an indenter
// off the block's centre (x from 1 to 7) with the block's top as the slave (a soft track under a stiff
// tip, as the run enforces it) gives the plane x = 4 through the indenter, not the block's own median
// x = 6, so each rank holds half of the zone (18 of the 36 top elements under the indenter) and the
// rest of the top by the side of the plane it lies on.
TEST(ContactPartition, PatchesAreCutThroughTheSmallerSurface) {
  const mesh::Mesh m = block_and_indenter(1);
  const inputs::ContactSpec track_slave = test::one_contact("top", "block_zmax", "tip", "indenter_zmin");
  std::vector<int> part = solver::parallel::partition_elements_rcb(m, 2, {1.0, 0.01, 1.0});
  solver::place_contact_patches(m, &track_slave, 2, part, {1.0, 0.01, 1.0});
  std::map<int, int> under_of;
  for (int e = 0; e < kBlockElements; ++e) {
    const auto c = centroid(m, e);
    if (c[2] != 3.5) continue;
    const int left_side = part[e] == part[0] ? 1 : 0;  // element 0 (x = 0.5) is left of the plane
    EXPECT_EQ(left_side, c[0] < 4.0 ? 1 : 0) << "element " << e << " at x = " << c[0];
    if (c[0] > 1 && c[0] < 7 && c[1] > 3 && c[1] < 9) ++under_of[part[e]];
  }
  ASSERT_EQ(under_of.size(), 2u);
  for (const auto& [p, count] : under_of) EXPECT_EQ(count, 18) << "part " << p;
  // The slave's own median, the old rule, would have cut at x = 6: 30 of the 36 on one side.
}

// A tall smaller body (an indenter 8 high on a 6 x 6 footprint, its bottom and four sides the master
// surface): its faces' box is longest in z, but the cuts go across the surface it stands on (the part
// of its box the slave's box overlaps), so the block's top is cut into four quadrants about the
// indenter's axis (x = 4, y = 6), 9 of the 36 elements under it in each. Cutting along the height would
// put the whole flat top in the lower patches.
TEST(ContactPartition, PatchesOfATallBodyAreCutAcrossTheSurface) {
  const mesh::Mesh m = block_and_indenter(1, 8);
  inputs::ContactSpec spec = test::one_contact("top", "block_zmax", "tip", "indenter_zmin");
  spec.surfaces[1].side_sets = {"indenter_zmin", "indenter_xmin", "indenter_xmax", "indenter_ymin", "indenter_ymax"};
  std::vector<int> part = solver::parallel::partition_elements(m, 4);
  solver::place_contact_patches(m, &spec, 4, part);
  std::map<int, int> part_of_quadrant, under_of;
  for (int e = 0; e < kBlockElements; ++e) {
    const auto c = centroid(m, e);
    if (c[2] != 3.5) continue;
    const int quadrant = (c[0] < 4.0 ? 0 : 1) + (c[1] < 6.0 ? 0 : 2);
    const auto [it, first] = part_of_quadrant.emplace(quadrant, part[e]);
    EXPECT_EQ(it->second, part[e]) << "element " << e << " at (" << c[0] << ", " << c[1] << ")";
    if (c[0] > 1 && c[0] < 7 && c[1] > 3 && c[1] < 9) ++under_of[part[e]];
  }
  std::set<int> distinct;
  for (const auto& [q, p] : part_of_quadrant) distinct.insert(p);
  EXPECT_EQ(distinct.size(), 4u) << "a part per quadrant";
  ASSERT_EQ(under_of.size(), 4u);
  for (const auto& [p, count] : under_of) EXPECT_EQ(count, 9) << "part " << p;
}
