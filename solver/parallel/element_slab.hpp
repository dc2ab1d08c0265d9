// SPDX-License-Identifier: MIT
// A contiguous slab of a mesh's elements held by one rank: the input of the distributed partition
// (face_dual_graph.hpp, ptscotch_partition.hpp). Rank r holds the elements [first, first + count) of
// the whole mesh, the ranks' slabs in rank order and together the whole mesh; each element as its 8
// node numbers in the whole mesh's numbering (hex8 order, mesh/mesh.hpp). Rank 0 cuts them from the mesh
// it read (element_slabs.hpp), or, with `set-up = distributed`, every rank generates its own from a
// generated mesh's plan or reads it from an Exodus file (source_parts.hpp, element_source.hpp).
#pragma once

#include <vector>

namespace tribex::solver::parallel {

struct ElementSlab {
  int first = 0;            // the slab's first element, in the whole mesh's numbering
  int count = 0;            // elements in the slab
  std::vector<int> nodes;   // [element][8] global node numbers
};

/// The even split of `elements` into `ranks` contiguous slabs: [rank + 1] the first element of each
/// (the first `elements % ranks` ranks hold one more), [0] = 0, [ranks] = elements.
std::vector<int> slab_offsets(int elements, int ranks);

}  // namespace tribex::solver::parallel
