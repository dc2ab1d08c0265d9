// SPDX-License-Identifier: MIT
#include "solver/parallel/sparse_rows.hpp"

#include <cmath>
#include <cstddef>

namespace tribex::solver::parallel {

int pack_nonzero_rows(const double* values, int width, const int* nodes, int count, double* message) {
  const std::size_t w = static_cast<std::size_t>(width);
  double* row = message;
  for (int j = 0; j < count; ++j) {
    const double* v = values + w * static_cast<std::size_t>(nodes[j]);
    bool nonzero = false;
    for (std::size_t i = 0; i < w; ++i) nonzero = nonzero || std::signbit(v[i]) || v[i] != 0.0;
    if (!nonzero) continue;
    *row++ = j;
    for (std::size_t i = 0; i < w; ++i) *row++ = v[i];
  }
  return static_cast<int>(row - message);
}

void apply_rows(const double* message, int length, int width, const int* nodes, int count, double* values, bool add) {
  const std::size_t w = static_cast<std::size_t>(width);
  const double* row = message;
  const double* end = message + length;
  for (int j = 0; j < count; ++j) {
    double* v = values + w * static_cast<std::size_t>(nodes[j]);
    const bool listed = row < end && static_cast<int>(*row) == j;
    for (std::size_t i = 0; i < w; ++i) {
      const double value = listed ? row[1 + i] : 0.0;
      v[i] = add ? v[i] + value : value;
    }
    if (listed) row += w + 1;
  }
}

}  // namespace tribex::solver::parallel
