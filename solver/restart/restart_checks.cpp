// SPDX-License-Identifier: MIT
// check_restart_values (restart_checks.hpp). The bounds: 0 <= step <= 1e15; start <= time <=
// termination (the deck's time control: a resumed run goes on from `time` to the termination time);
// every time step finite, >= 0 and at most the span; the schedules' next output times within
// [start, termination + span] (results_next only when the deck writes results: 0 otherwise) (solver/output/schedule.hpp steps past any of them in bounded work,
// this keeps the output times of the resumed run those of the deck); wall times finite >= 0 or
// NaN (not recorded).
#include "solver/restart/restart_checks.hpp"

#include <cmath>
#include <cstdio>

namespace tribex::solver {
namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& name, const std::string& what) {
  throw SetupError(path + ": error: restart dataset '" + name + "' " + what +
                   " (an edited or damaged restart file?); restart from a file a tribex run wrote");
}

std::string number(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", x);
  return b;
}

void check_real(const StateArchive& a, const std::string& path, const std::string& name, double lo, double hi,
                const std::string& bound) {
  if (!a.has(name)) return;  // the reader that needs it names it (StateArchive::array)
  const double x = a.scalar(name);
  if (!std::isfinite(x) || x < lo || x > hi) refuse(path, name, "= " + number(x) + " is not " + bound);
}

}  // namespace

void check_restart_values(const StateArchive& a, const inputs::TimeControlSpec& tc, bool has_results,
                          const std::string& path) {
  const long long step = a.integer("step");
  if (step < 0 || step > 1'000'000'000'000'000LL)
    refuse(path, "step", "= " + std::to_string(step) + " is not a step number in [0, 1e15]");
  const double t0 = tc.start_time, t1 = tc.termination_time, span = t1 - t0;
  const std::string in_span = "within the deck's time span [" + number(t0) + " s, " + number(t1) + " s]";
  check_real(a, path, "time", t0, t1 + 1e-9 * span, in_span);
  for (const char* name : {"dt_n", "dt_half", "dt_prev_half", "stable_dt"})
    check_real(a, path, name, 0.0, span, "a time step in [0 s, " + number(span) + " s] (the deck's span)");
  for (const char* name : {"history_next", "results_next"})
    if (has_results || std::string(name) == "history_next") check_real(a, path, name, t0, t1 + span,
               "a next output time within [" + number(t0) + " s, " + number(t1 + span) + " s] (the deck's start "
               "time to its termination time plus its span)");
  for (const char* name : {"run_wall_seconds", "run_loop_seconds"}) {
    if (!a.has(name)) continue;
    const double x = a.scalar(name);
    if (!std::isnan(x) && !(std::isfinite(x) && x >= 0)) refuse(path, name, "= " + number(x) + " is not a time >= 0 s");
  }
}

}  // namespace tribex::solver
