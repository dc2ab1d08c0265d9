// SPDX-License-Identifier: MIT
// The step the geometric partitions take (the k-d clusters of element_clusters.cpp, the coordinate
// bisection of the volume, parallel/partition.hpp, and the contact patches of
// solver/parallel/contact_partition.cpp): split a range of points at a given rank along the longest side of
// their box, or (bisect_like) divide one set of points by the planes that bisect another. Points are
// `items` (indices into `centre`, [item][3]); ties by item number, so the same points give the same
// split on every machine.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::solver::parallel {

/// [element][3] the element centroids (the mean of the 8 nodes), as `Real` (the clusters keep float:
/// 12 B per element on rank 0).
template <class Real>
std::vector<Real> element_centres(const mesh::Mesh& mesh) {
  const std::size_t ne = static_cast<std::size_t>(mesh.element_count());
  std::vector<Real> centre(3 * ne, Real(0));
  for (std::size_t e = 0; e < ne; ++e)
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        centre[3 * e + i] +=
            static_cast<Real>(0.125 * mesh.coordinates[3 * static_cast<std::size_t>(mesh.connectivity[8 * e + a]) + i]);
  return centre;
}

/// Multipliers of the coordinates when the sides of a box are compared (the deck's `coordinate scale`,
/// LS-DYNA's decomposition transformation SX SY SZ): a small factor on an axis keeps the cuts along it.
using AxisScale = std::array<double, 3>;
inline constexpr AxisScale kUnitScale{1.0, 1.0, 1.0};

/// An axis-aligned box of points.
template <class Real>
struct PointBox {
  Real lo[3], hi[3];
};

/// The bounding box of points items[begin, end) (non-empty).
template <class Real>
PointBox<Real> box_of(const std::vector<int>& items, std::size_t begin, std::size_t end, const std::vector<Real>& centre) {
  PointBox<Real> box;
  for (int i = 0; i < 3; ++i) box.lo[i] = box.hi[i] = centre[3 * static_cast<std::size_t>(items[begin]) + i];
  for (std::size_t k = begin; k < end; ++k)
    for (int i = 0; i < 3; ++i) {
      const Real c = centre[3 * static_cast<std::size_t>(items[k]) + i];
      box.lo[i] = std::min(box.lo[i], c);
      box.hi[i] = std::max(box.hi[i], c);
    }
  return box;
}

/// The axis whose side `side[axis]` is the longest after `scale`; the first among equals.
template <class Real>
int longest_axis(const Real side[3], const AxisScale& scale) {
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (scale[i] * side[i] > scale[axis] * side[axis]) axis = i;
  return axis;
}

/// Reorders items[begin, end) so that the first `mid - begin` are the lowest along `axis`
/// (std::nth_element: linear time, neither half sorted; ties by item number).
template <class Real>
void split_along_axis(std::vector<int>& items, std::size_t begin, std::size_t mid, std::size_t end,
                      const std::vector<Real>& centre, int axis) {
  auto at = [&](int item) { return centre[3 * static_cast<std::size_t>(item) + axis]; };
  const auto first = items.begin();
  std::nth_element(first + static_cast<std::ptrdiff_t>(begin), first + static_cast<std::ptrdiff_t>(mid),
                   first + static_cast<std::ptrdiff_t>(end), [&](int a, int b) {
                     const Real ca = at(a), cb = at(b);
                     return ca < cb || (ca == cb && a < b);
                   });
}

/// Reorders items[begin, end) so that the first `mid - begin` are the lowest along the longest side
/// of their bounding box, sides measured after `scale`.
template <class Real>
void split_along_longest_side(std::vector<int>& items, std::size_t begin, std::size_t mid, std::size_t end,
                              const std::vector<Real>& centre, const AxisScale& scale = kUnitScale) {
  if (end - begin < 2) return;
  const PointBox<Real> box = box_of(items, begin, end, centre);
  const Real side[3] = {box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]};
  split_along_axis(items, begin, mid, end, centre, longest_axis(side, scale));
}

/// Recursive coordinate bisection: items[begin, end) into parts first .. first + count - 1, each part's
/// share of the items proportional to its count of parts (an odd count splits count/2 : the rest);
/// part_of[item] receives the part.
template <class Real>
void bisect_into_parts(std::vector<int>& items, std::size_t begin, std::size_t end, int first, int count,
                       const std::vector<Real>& centre, std::vector<int>& part_of, const AxisScale& scale = kUnitScale) {
  if (count == 1 || end - begin <= 1) {
    for (std::size_t k = begin; k < end; ++k) part_of[static_cast<std::size_t>(items[k])] = first;
    return;
  }
  const int left = count / 2;
  const std::size_t mid = begin + (end - begin) * static_cast<std::size_t>(left) / static_cast<std::size_t>(count);
  split_along_longest_side(items, begin, mid, end, centre, scale);
  bisect_into_parts(items, begin, mid, first, left, centre, part_of, scale);
  bisect_into_parts(items, mid, end, first + left, count - left, centre, part_of, scale);
}

/// bisect_into_parts's cuts taken from one set of points and applied to another: the `reference`
/// items [rbegin, rend) (points `reference_centre`) are split at their median as there, along the
/// longest side (after `scale`) of the part of their box that the targets' box overlaps (a tall body
/// above a flat surface is cut across the surface, not along its height; disjoint boxes: the
/// references' own box), and each cut is the plane midway between the two halves; the `targets` items
/// [tbegin, tend) (points `target_centre`) go to the side of each plane they lie on (on it: the upper
/// side), and part_of[target] receives the part. Used where the work lies near a smaller body than the
/// one being divided (the contact patches: solver/parallel/contact_partition.cpp).
template <class Real>
void bisect_like(std::vector<int>& reference, std::size_t rbegin, std::size_t rend, const std::vector<Real>& reference_centre,
                 std::vector<int>& targets, std::size_t tbegin, std::size_t tend, const std::vector<Real>& target_centre,
                 int first, int count, std::vector<int>& part_of, const AxisScale& scale = kUnitScale) {
  if (tbegin == tend) return;
  if (count == 1 || rend - rbegin <= 1) {
    for (std::size_t k = tbegin; k < tend; ++k) part_of[static_cast<std::size_t>(targets[k])] = first;
    return;
  }
  const PointBox<Real> rbox = box_of(reference, rbegin, rend, reference_centre);
  const PointBox<Real> tbox = box_of(targets, tbegin, tend, target_centre);
  Real overlap[3], own[3];
  bool disjoint = false;
  for (int i = 0; i < 3; ++i) {
    own[i] = rbox.hi[i] - rbox.lo[i];
    overlap[i] = std::min(rbox.hi[i], tbox.hi[i]) - std::max(rbox.lo[i], tbox.lo[i]);
    disjoint = disjoint || overlap[i] < 0;
  }
  const int axis = longest_axis(disjoint ? own : overlap, scale);
  const int left = count / 2;
  const std::size_t mid = rbegin + (rend - rbegin) * static_cast<std::size_t>(left) / static_cast<std::size_t>(count);
  split_along_axis(reference, rbegin, mid, rend, reference_centre, axis);
  auto ref_at = [&](std::size_t k) { return reference_centre[3 * static_cast<std::size_t>(reference[k]) + axis]; };
  Real lower_top = ref_at(rbegin);
  for (std::size_t k = rbegin; k < mid; ++k) lower_top = std::max(lower_top, ref_at(k));
  const Real plane = lower_top + (ref_at(mid) - lower_top) / 2;  // ref_at(mid): the upper half's lowest
  const auto split = std::partition(targets.begin() + static_cast<std::ptrdiff_t>(tbegin),
                                    targets.begin() + static_cast<std::ptrdiff_t>(tend),
                                    [&](int t) { return target_centre[3 * static_cast<std::size_t>(t) + axis] < plane; });
  const std::size_t tmid = static_cast<std::size_t>(split - targets.begin());
  bisect_like(reference, rbegin, mid, reference_centre, targets, tbegin, tmid, target_centre, first, left, part_of, scale);
  bisect_like(reference, mid, rend, reference_centre, targets, tmid, tend, target_centre, first + left, count - left,
              part_of, scale);
}

}  // namespace tribex::solver::parallel
