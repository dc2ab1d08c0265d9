// SPDX-License-Identifier: MIT
// When an output is due: "every N steps or every dt seconds of simulated time", plus the first and
// the last state. history.csv and results.h5 each keep one; restart files carry `next()`.
#pragma once

#include <optional>

namespace tribex::solver {

class Schedule {
 public:
  Schedule(std::optional<double> time_increment, std::optional<int> step_increment, double start)
      : dt_(time_increment), steps_(step_increment), next_(start) {}
  bool due(double t, long step, bool final) const {
    if (final || step == 0) return true;
    if (steps_) return step % *steps_ == 0;
    return t >= next_ - 1e-9 * *dt_;
  }
  double next() const { return next_; }
  void set_next(double t) { next_ = t; }
  void done(double t) {
    if (dt_)
      while (next_ <= t + 1e-9 * *dt_) next_ += *dt_;
  }

 private:
  std::optional<double> dt_;
  std::optional<int> steps_;
  double next_;
};

}  // namespace tribex::solver
