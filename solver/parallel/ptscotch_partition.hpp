// SPDX-License-Identifier: MIT
// The element partition computed by all the ranks together (`begin decomposition` / `method =
// ptscotch`, solver/README.md "Parallel runs"): PT-Scotch's SCOTCH_dgraphPart on the distributed dual
// graph of the elements (face_dual_graph.hpp), each rank passing the rows of its slab of elements and
// receiving the part of each. The weights are those of the METIS path (parallel/partition.cpp): every
// element weighs 1 and every shared face 1 (the METIS element graph carries no weights; its cluster
// graph weighs a cluster by its element count, the same thing). The strategy is PT-Scotch's default
// k-way mapping strategy (SCOTCH_stratDgraphMapBuild) with a load imbalance of at most kImbalance, run
// with one thread per rank, deterministic and with a fixed random seed, so that a given mesh on a given
// rank count is partitioned the same way every time (a different rank count gives a different, equally
// valid partition: PT-Scotch's coarsening follows the distribution of the graph).
#pragma once

#include <vector>

#include "solver/parallel/face_dual_graph.hpp"

namespace tribex::solver::parallel {

/// The largest relative excess of a part's weight over the even share the strategy is given.
inline constexpr double kPtScotchImbalance = 0.03;

/// Collective over MPI_COMM_WORLD: [local element] its part in [0, parts) of the graph `rows`
/// (face_dual_graph). One part: all zeros (PT-Scotch not called). Throws std::runtime_error, on every
/// rank alike, for more parts than elements or when PT-Scotch fails.
std::vector<int> ptscotch_parts(const DualGraphRows& rows, int parts);

}  // namespace tribex::solver::parallel
