// SPDX-License-Identifier: MIT
// Piecewise-linear function of time from a deck table, held constant outside its range.
#pragma once

#include <vector>

#include "inputs/deck.hpp"

namespace tribex::solver {

class TimeFunction {
 public:
  TimeFunction() = default;
  explicit TimeFunction(const inputs::FunctionSpec& spec) : t_(spec.abscissa), f_(spec.ordinate) {}
  /// f(t); amortised O(1) for increasing t (the segment of the last call is tried first).
  double operator()(double t) const {
    if (t <= t_.front()) return f_.front();
    if (t >= t_.back()) return f_.back();
    if (t < t_[hint_] || t > t_[hint_ + 1]) {
      std::size_t lo = 0, hi = t_.size() - 1;
      while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (t_[mid] <= t ? lo : hi) = mid;
      }
      hint_ = lo;
    }
    const double s = (t - t_[hint_]) / (t_[hint_ + 1] - t_[hint_]);
    return f_[hint_] + s * (f_[hint_ + 1] - f_[hint_]);
  }

 private:
  std::vector<double> t_, f_;
  mutable std::size_t hint_ = 0;
};

}  // namespace tribex::solver
