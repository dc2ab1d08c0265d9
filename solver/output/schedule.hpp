// SPDX-License-Identifier: MIT
// When an output is due: "every N steps or every dt seconds of simulated time", plus the first and
// the last state. history.csv and results.h5 each keep one; restart files carry `next()`.
// Bounded (issue 54, item 9): `done` advances the next output time past t in at most 64 additions
// and one jump, whatever next() and t are (a restart file's, a tiny increment); the deck's
// increments are checked against kMaxOutputTimes (inputs/deck_builder.cpp) and a restart file's
// next times against the run's span (solver/restart/restart_checks.cpp) before the loop.
#pragma once

#include <cmath>
#include <limits>
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
    if (!dt_) return;
    const double dt = *dt_, tol = 1e-9 * dt;
    // The usual case: one interval (or a few, when the interval is below the time step), added one
    // at a time so that the output times are those of the uninterrupted sum.
    for (int i = 0; i < 64 && next_ <= t + tol; ++i) next_ += dt;
    if (next_ <= t + tol) next_ += (std::floor((t + tol - next_) / dt) + 1.0) * dt;  // far behind: one jump
    // An increment below the resolution of t (next + dt == next): the next output is the next step.
    if (!(next_ > t + tol)) next_ = std::nextafter(t + tol, std::numeric_limits<double>::infinity());
  }

 private:
  std::optional<double> dt_;
  std::optional<int> steps_;
  double next_;
};

}  // namespace tribex::solver
