// SPDX-License-Identifier: MIT
// The checks the file-slice tests (exodus_slab_test.cpp, msh_slab_test.cpp) make on a routed element source
// (solver/parallel/file_slice_source.hpp, over Exodus or gmsh slices): the part this rank builds from its slices is
// split_mesh's part of the serial mesh under the same partition, under the two partitions both tests use.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/element_slab.hpp"
#include "solver/parallel/file_slice_source.hpp"
#include "solver/parallel/mesh_part.hpp"
#include "solver/parallel/source_parts.hpp"
#include "tests/support/mesh_part_equal.hpp"

namespace tribex::test {

// Calls `check(part, what)` with the two partitions of `elements`: the slabs themselves (rank r owns slab r)
// and a scattered one (every rank's part drawn from every slab).
inline void for_slab_and_scattered_partitions(int elements,
                                               const std::function<void(const std::vector<int>&, const char*)>& check) {
  const int ranks = solver::parallel::size();
  std::vector<int> slabs(static_cast<std::size_t>(elements)), scattered(slabs.size());
  const std::vector<int> offset = solver::parallel::slab_offsets(elements, ranks);
  for (int r = 0; r < ranks; ++r) std::fill(slabs.begin() + offset[r], slabs.begin() + offset[r + 1], r);
  for (int e = 0; e < elements; ++e) scattered[static_cast<std::size_t>(e)] = (7 * e + e / 13) % ranks;
  check(slabs, "slab partition");
  check(scattered, "scattered partition");
}

// The routed `source` against the serial mesh `whole` under `part` [element]: this rank's part, the nodes on
// partition boundaries, the slab's connectivity, and the elements of the side sets `sets` (and of one set the
// file lacks: none).
inline void expect_source_part(solver::parallel::FileSliceSource& source, const mesh::Mesh& whole,
                               const std::vector<int>& part, std::vector<std::string> sets) {
  namespace par = solver::parallel;
  const std::vector<int> offset = par::slab_offsets(whole.element_count(), par::size());
  const std::vector<int> slab_part(part.begin() + offset[par::rank()], part.begin() + offset[par::rank() + 1]);
  const par::SourcePart got = par::source_part(source, slab_part);
  const par::NodeHolders holders = par::node_holders(whole, part);
  expect_same_part(got.part, par::split_mesh(whole, part, holders, par::rank()));
  long long shared = 0;
  for (int n = 0; n < whole.node_count(); ++n) shared += holders.count(n) > 1;
  EXPECT_EQ(got.shared_nodes, shared);
  const std::vector<int> slab = source.slab_nodes();
  EXPECT_TRUE(std::equal(slab.begin(), slab.end(), whole.connectivity.begin() + 8 * offset[par::rank()]));
  std::vector<int> want;
  for (const auto& name : sets)
    for (const auto& s : whole.side_sets.at(name)) want.push_back(s.element);
  std::sort(want.begin(), want.end());
  want.erase(std::unique(want.begin(), want.end()), want.end());
  sets.push_back("no_such_set");
  EXPECT_EQ(source.side_set_elements(sets), want);
}

}  // namespace tribex::test
