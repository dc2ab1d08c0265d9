// SPDX-License-Identifier: MIT
// The step both geometric partitions take (the k-d clusters of element_clusters.cpp and the contact
// patches of solver/contact_partition.cpp): split a range of points at a given rank along the longest
// side of their box. Points are `items` (indices into `centre`, [item][3]); ties by item number, so
// the same points give the same split on every machine.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tribex::solver::parallel {

/// Reorders items[begin, end) so that the first `mid - begin` are the lowest along the longest side
/// of their bounding box (std::nth_element: linear time, neither half sorted).
template <class Real>
void split_along_longest_side(std::vector<int>& items, std::size_t begin, std::size_t mid, std::size_t end,
                              const std::vector<Real>& centre) {
  if (end - begin < 2) return;
  auto at = [&](int item, int axis) { return centre[3 * static_cast<std::size_t>(item) + axis]; };
  Real lo[3], hi[3];
  for (int i = 0; i < 3; ++i) lo[i] = hi[i] = at(items[begin], i);
  for (std::size_t k = begin; k < end; ++k)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], at(items[k], i));
      hi[i] = std::max(hi[i], at(items[k], i));
    }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (hi[i] - lo[i] > hi[axis] - lo[axis]) axis = i;
  const auto first = items.begin();
  std::nth_element(first + static_cast<std::ptrdiff_t>(begin), first + static_cast<std::ptrdiff_t>(mid),
                   first + static_cast<std::ptrdiff_t>(end), [&](int a, int b) {
                     const Real ca = at(a, axis), cb = at(b, axis);
                     return ca < cb || (ca == cb && a < b);
                   });
}

}  // namespace tribex::solver::parallel
