// SPDX-License-Identifier: MIT
// The run guards (solver/guards/README.md): watched every step, they turn a run that goes physically
// wrong into warnings (each once, at its first crossing, its maximum kept) and, past a limit, into a
// numerical failure (exit 3). Set-up warnings (the model's) open the list.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contact/contact_manager.hpp"
#include "inputs/deck.hpp"
#include "solver/energy.hpp"
#include "solver/guards/run_warning.hpp"

namespace tribex::solver {

struct StateArchive;

/// What the messages name beside a warning's numbers (SetupFindings' texts).
struct WarningContext {
  std::string one_point_contact;     // the interactions and blocks of an unsafe_choice raised in the run
  std::string contact_interactions;  // the energy warning's contact source
  bool mass_scaled = false;
  std::vector<std::string> block_names;  // the model's blocks, for large_strain
};

/// The message of a run-time warning from its numbers (also for warnings read back from a restart file).
std::string describe(const RunWarning& w, const WarningContext& context = {});

/// Contact penetration, in local element sizes, that marks high pressure for one-point elements under
/// node-to-face penalty contact (solver/guards/README.md).
inline constexpr double one_point_penetration = 0.1;

class RunGuards {
 public:
  /// `say` prints a warning as it is raised (terminal and log); `expected_steps` sizes the quasi-static
  /// samples once (no allocation in the loop).
  RunGuards(const inputs::GuardSpec& spec, SetupFindings setup, long expected_steps,
            std::function<void(const RunWarning&)> say);

  /// At time n of step `step` (after its outputs). Throws NumericalFailure past a limit; `contact`
  /// null without contact. `translational_kinetic`: the kinetic energy of the blocks' mean translation
  /// (BlockTranslation), needed on the steps where wants_sample() is true.
  void observe(long step, double t, const Energies& energies, const contact::ContactTotals* contact,
               double translational_kinetic = 0.0);

  /// Every StrainGuard stride: the largest principal strain of the small-strain elastic blocks (solver/guards/
  /// strain_guard.hpp), warned once past small_strain_warning naming the block.
  void observe_strain(long step, double t, double value, int element, int block);

  /// Whether this step's observe takes a quasi-static sample (and so needs translational_kinetic).
  bool wants_sample(long step) const { return spec_.quasi_static && step % stride_ == 0; }

  /// At the end of the run (any exit): the quasi-static check over the loaded part of the run. Returns
  /// the failure message when a mass-scaled run passed `maximum kinetic energy ratio` there (the run
  /// then ends with exit 3), else empty.
  std::string finish();

  const std::vector<RunWarning>& warnings() const { return warnings_; }

  /// The run-time warnings and the quasi-static samples, for a restart file (set-up warnings are
  /// made again by the resumed run's set-up).
  void save(StateArchive& archive) const;
  void restore(const StateArchive& archive);

 private:
  struct Watch {
    WarningKind kind;
    double threshold;
    int entry = -1;  // index in warnings_ once raised
  };
  void watch(Watch& w, long step, double t, double value, int node, int block = -1);
  /// The energy warning's likely source from the ledger's change since clean_ (run_guards.cpp).
  void attribute(const Energies& now, RunWarning& w) const;
  std::string scan_quasi_static();
  /// The mid-run stop of `maximum kinetic energy ratio` (run_guards.cpp, sustained_fraction); throws.
  void watch_sustained_kinetic(long step, double t, double kinetic, double internal);
  RunWarning& entry(const Watch& w) { return warnings_[static_cast<std::size_t>(w.entry)]; }
  std::string text(const RunWarning& w) const { return describe(w, context_); }

  inputs::GuardSpec spec_;
  std::vector<RunWarning> warnings_;
  std::function<void(const RunWarning&)> say_;
  Watch energy_, penetration_, motion_, one_point_, strain_;
  WarningContext context_;  // from SetupFindings
  // The ledger at the last step whose energy error was at most half the warning (the attribution's base).
  Energies clean_;
  long clean_step_ = 0;
  const Energies* observed_ = nullptr;  // this step's ledger while observe() runs (for attribute)
  // Quasi-static samples (step, t, kinetic, internal) every stride_ steps; thinned in place when full.
  std::vector<double> samples_;
  std::size_t capacity_ = 0;
  long stride_ = 1;
  // The mid-run kinetic-energy stop: the peak internal energy so far, J; the step and time the current
  // unbroken excess began (-1: none); its length that stops the run, steps.
  double running_peak_ = 0.0;
  long excess_since_ = -1;
  double excess_since_time_ = 0.0;
  long sustained_steps_ = 1;
};


}  // namespace tribex::solver
