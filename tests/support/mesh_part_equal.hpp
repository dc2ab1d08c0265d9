// SPDX-License-Identifier: MIT
// expect_same_mesh / expect_same_part: two meshes or two ranks' parts (solver/parallel/mesh_part.hpp) are the same, field by field, the
// coordinates bit for bit (the distributed set-ups must give split_mesh's part exactly; a part must survive
// its byte form). GoogleTest EXPECTs, so every difference is reported.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "solver/parallel/mesh_part.hpp"

namespace tribex::test {

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

inline void expect_same_mesh(const mesh::Mesh& got, const mesh::Mesh& want) {
  EXPECT_TRUE(same_bits(got.coordinates, want.coordinates));
  EXPECT_EQ(got.connectivity, want.connectivity);
  ASSERT_EQ(got.blocks.size(), want.blocks.size());
  for (std::size_t b = 0; b < got.blocks.size(); ++b) {
    EXPECT_EQ(got.blocks[b].name, want.blocks[b].name);
    EXPECT_EQ(got.blocks[b].first_element, want.blocks[b].first_element);
    EXPECT_EQ(got.blocks[b].element_count, want.blocks[b].element_count);
  }
  EXPECT_EQ(got.node_sets, want.node_sets);
  EXPECT_EQ(got.side_sets, want.side_sets);
}

inline void expect_same_part(const solver::parallel::MeshPart& got, const solver::parallel::MeshPart& want) {
  EXPECT_EQ(got.global_element, want.global_element);
  EXPECT_EQ(got.global_node, want.global_node);
  expect_same_mesh(got.mesh, want.mesh);
  EXPECT_EQ(got.holder_offset, want.holder_offset);
  EXPECT_EQ(got.holder_rank, want.holder_rank);
  EXPECT_EQ(got.global_node_count, want.global_node_count);
  EXPECT_EQ(got.global_element_count, want.global_element_count);
  EXPECT_EQ(got.node_set_size, want.node_set_size);
  EXPECT_EQ(got.side_set_size, want.side_set_size);
}

}  // namespace tribex::test
