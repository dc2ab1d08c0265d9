// SPDX-License-Identifier: MIT
// Geometric grading: sizes h q^k, k = 1..n, sum h q (q^n - 1)/(q - 1) = L (for q = 1: n h = L).
#include "mesh/afm/graded_axis.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {
namespace {

constexpr int kMaxGradedCells = 10'000'000;

double series(double q, int n) {  // sum_{k=1..n} q^k
  double s = 0.0, p = 1.0;
  for (int k = 0; k < n; ++k) s += (p *= q);
  return s;
}

}  // namespace

std::vector<double> graded_sizes(double length, double h, double ratio) {
  if (!(length > 0.0)) return {};
  if (length <= h * ratio) return {length};
  // The smallest n with h series(ratio, n) >= L, the series summed as it grows (the same additions as
  // series(); bounded: issue 54, item 9, at most kMaxGradedCells, where ratio 1 and a tiny h would spin).
  int n = 1;
  double term = ratio, sum = ratio;
  while (h * sum < length) {
    if (n >= kMaxGradedCells)
      throw MeshError("a graded axis of " + std::to_string(length) + " m at element size " + std::to_string(h) +
                      " m needs more than 10000000 elements; give a larger element size");
    sum += (term *= ratio);
    ++n;
  }
  if (h * n > length) {  // even uniform elements of h would overshoot: ceil(L/h) equal ones, each <= h
    const int m = static_cast<int>(std::ceil(length / h - 1e-9));
    return std::vector<double>(static_cast<std::size_t>(m), length / m);
  }
  double lo = 1.0, hi = ratio;  // h series(q, n) is increasing in q: bisect for = L
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (h * series(mid, n) < length ? lo : hi) = mid;
  }
  std::vector<double> s(static_cast<std::size_t>(n));
  double p = h;
  for (auto& v : s) v = (p *= lo);
  return s;
}

std::vector<double> graded_axis(double lo, double hi, double track_lo, double track_hi, double h, double ratio) {
  track_lo = std::clamp(track_lo, lo, hi);
  track_hi = std::clamp(track_hi, track_lo, hi);
  if (track_lo - lo < 0.25 * h) track_lo = lo;
  if (hi - track_hi < 0.25 * h) track_hi = hi;
  const int nt = std::max(1, static_cast<int>(std::ceil((track_hi - track_lo) / h - 1e-9)));
  const double ht = (track_hi - track_lo) / nt;
  std::vector<double> x;
  const auto left = graded_sizes(track_lo - lo, ht, ratio);
  x.push_back(lo);
  for (auto it = left.rbegin(); it != left.rend(); ++it) x.push_back(x.back() + *it);
  x.back() = track_lo;
  for (int i = 1; i <= nt; ++i) x.push_back(track_lo + (track_hi - track_lo) * i / nt);
  for (double s : graded_sizes(hi - track_hi, ht, ratio)) x.push_back(x.back() + s);
  x.back() = hi;
  return x;
}

}  // namespace tribex::mesh::afm
