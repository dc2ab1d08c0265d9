// SPDX-License-Identifier: MIT
// The outline of a generated asperity that the tests build in code: one call instead of six assignments.
#pragma once

#include "mesh/asperity.hpp"

namespace tribex::test {

/// A generated asperity with the sphere's `radius`, the tip's `tip_width` and `tip_height`, the substrate's
/// `substrate_width` and `substrate_depth` and `element_size` at the contact (all m); every other key of
/// mesh::AsperitySpec at its default, for the test to set.
inline mesh::AsperitySpec asperity_outline(double radius, double tip_width, double tip_height, double substrate_width,
                                           double substrate_depth, double element_size) {
  mesh::AsperitySpec a;
  a.radius = radius;
  a.tip_width = tip_width;
  a.tip_height = tip_height;
  a.substrate_width = substrate_width;
  a.substrate_depth = substrate_depth;
  a.element_size = element_size;
  return a;
}

}  // namespace tribex::test
