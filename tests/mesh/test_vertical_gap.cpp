// SPDX-License-Identifier: MIT
// smallest_vertical_gap (mesh/vertical_gap.hpp): the tip placement of `gap above surface`.
#include <gtest/gtest.h>

#include "mesh/asperity.hpp"
#include "mesh/box.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/vertical_gap.hpp"

namespace tribex::mesh {
namespace {

Mesh box(const std::string& name, std::array<double, 3> origin, std::array<double, 3> size, std::array<int, 3> n) {
  BoxSpec b;
  b.name = name;
  b.origin = origin;
  b.size = size;
  b.intervals = n;
  return generate_box(b);
}

// A sphere-tipped tip over a flat top: the apex is the closest point, directly above a node.
TEST(VerticalGap, SphereApexOverAFlatTopIsTheApexHeight) {
  Mesh m = box("flat", {-20e-9, -20e-9, -10e-9}, {40e-9, 40e-9, 10e-9}, {8, 8, 2});
  AsperitySpec tip;
  tip.radius = 27e-9;
  tip.element_size = 1e-9;
  tip.tip_only = true;
  tip.place_apex = true;
  tip.apex = {0.0, 0.0, 0.7e-9};
  append(m, generate_asperity(tip));
  const auto gap = smallest_vertical_gap(m, "tip_surface", "flat_zmax");
  ASSERT_TRUE(gap.has_value());
  EXPECT_NEAR(*gap, 0.7e-9, 1e-21);
}

// A peak of the lower surface under the middle of an upper face: no upper node sees it (each sees the
// faceted slope, lower than the peak), so only the lower set's nodes find the gap 1 - 0.4.
TEST(VerticalGap, PeakUnderAFaceIsFoundFromTheLowerSurface) {
  Mesh m = box("lower", {0, 0, -1}, {4, 4, 1}, {4, 4, 1});
  const int peak = 2 + 5 * (2 + 5 * 1);  // node (2, 2) of the top layer
  ASSERT_DOUBLE_EQ(m.coordinates[3 * peak + 2], 0.0);
  m.coordinates[3 * peak + 2] = 0.4;
  append(m, box("upper", {0.5, 0.5, 1}, {3, 3, 1}, {2, 2, 1}));  // nodes at 0.5, 2, 3.5: the peak at 2, 2 is one
  Mesh shifted = m;
  for (int n = 0; n < shifted.node_count(); ++n)
    if (shifted.coordinates[3 * n + 2] >= 1.0) shifted.coordinates[3 * n] += 0.25;  // now under a face's middle
  EXPECT_NEAR(*smallest_vertical_gap(m, "upper_zmin", "lower_zmax"), 0.6, 1e-15);
  EXPECT_NEAR(*smallest_vertical_gap(shifted, "upper_zmin", "lower_zmax"), 0.6, 1e-15);
}

TEST(VerticalGap, DisjointFootprintsHaveNoGapAndMissingSetsAreErrors) {
  Mesh m = box("a", {0, 0, 0}, {1, 1, 1}, {1, 1, 1});
  append(m, box("b", {5, 5, 2}, {1, 1, 1}, {1, 1, 1}));
  EXPECT_FALSE(smallest_vertical_gap(m, "b_zmin", "a_zmax").has_value());
  EXPECT_THROW(smallest_vertical_gap(m, "b_zmin", "nothing"), MeshError);
}

}  // namespace
}  // namespace tribex::mesh
