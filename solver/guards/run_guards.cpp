// SPDX-License-Identifier: MIT
#include "solver/guards/run_guards.hpp"

#include <algorithm>
#include <cmath>

#include "solver/errors.hpp"
#include "solver/output/output_tables.hpp"
#include "solver/output/run_log.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {
namespace {

// The quasi-static check looks at the loaded part of the run only: where the internal energy is at
// least this fraction of its peak. Before contact builds up (a driven tip approaching, the first
// rings) and after unloading, kinetic energy is legitimately comparable to a small internal energy.
constexpr double loaded_fraction = 0.1;
// The mid-run stop of `maximum kinetic energy ratio`: the limit exceeded at every sample over this
// fraction of the expected run, where the internal energy is at least `loaded_fraction` of its peak so far.
// A short excess (the first contact's ring, where the peak so far is the current tiny internal energy)
// does not stop the run; the end-of-run scan still judges every loaded sample against the whole run's peak.
constexpr double sustained_fraction = 0.05;
constexpr std::size_t sample_width = 4;  // step, t, kinetic, internal
constexpr long target_samples = 4096;

std::string where(long step, double t) { return format("step %ld, t = %.6g s", step, t); }

// Energy ratios read as percentages; penetration and motion as fractions of a length.
std::string shown(WarningKind kind, double value) {
  const bool percent = kind == WarningKind::energy_error || kind == WarningKind::kinetic_energy;
  return percent ? format("%.3g %%", 100 * value) : format("%.3g", value);
}

}  // namespace

const char* kind_name(WarningKind kind) {
  switch (kind) {
    case WarningKind::energy_error: return "energy_error";
    case WarningKind::penetration: return "penetration";
    case WarningKind::kinetic_energy: return "kinetic_energy";
    case WarningKind::contact_motion: return "contact_motion";
    case WarningKind::adhesion_cutoff: return "adhesion_cutoff";
    case WarningKind::unsafe_choice: return "unsafe_choice";
  }
  return "unknown";
}

std::string describe(const RunWarning& w, const std::string& one_point_contact) {
  std::string what;
  switch (w.kind) {
    case WarningKind::energy_error:
      what = format("energy balance error %.3g %% at %s is above 'energy error warning' %.3g %%: energy is not "
                    "conserved; see contact_work and the dissipation columns of history.csv",
                    100 * w.value, where(w.step, w.time).c_str(), 100 * w.threshold);
      break;
    case WarningKind::penetration:
      what = format("contact penetration %.3g of the local element size at node %d, %s, is above 'penetration "
                    "warning' %.3g: the penalty is soft for this load; raise 'penalty scale factor', refine the "
                    "contact surfaces or use 'enforcement = mortar'",
                    w.value, w.node + 1, where(w.step, w.time).c_str(), w.threshold);
      break;
    case WarningKind::kinetic_energy:
      what = format("kinetic energy (less the blocks' mean translation) %.3g %% of internal energy at %s in a run "
                    "declared 'quasi static' (above 'kinetic energy warning' %.3g %%, checked where the internal "
                    "energy is at least %.0f %% of its peak): inertia matters; drive slower or damp ('mass damping "
                    "coefficient')",
                    100 * w.value, where(w.step, w.time).c_str(), 100 * w.threshold, 100 * loaded_fraction);
      break;
    case WarningKind::contact_motion:
      what = format("contact surfaces move %.3g of the capture distance in one step (node %d), %s, above 'contact "
                    "motion warning' %.3g: contact can be missed (tunnelling); drive slower, lower 'time step scale "
                    "factor' or raise 'search margin'",
                    w.value, w.node + 1, where(w.step, w.time).c_str(), w.threshold);
      break;
    case WarningKind::unsafe_choice:
      what = format("contact penetration %.3g of the local element size at node %d, %s, shows high pressure on "
                    "one-point (mean_quadrature) elements under node-to-face penalty contact (%s): their point forces "
                    "excite hourglass modes (energy injected, elements invert); use 'formulation = fully_integrated' "
                    "for the contact blocks or 'enforcement = mortar'",
                    w.value, w.node + 1, where(w.step, w.time).c_str(), one_point_contact.c_str());
      break;
    default:
      return w.message;  // set-up warnings carry their own text
  }
  if (w.max_step != w.step) what += "; largest " + shown(w.kind, w.max_value) + " at " + where(w.max_step, w.max_time);
  return what;
}

RunGuards::RunGuards(const inputs::GuardSpec& spec, SetupFindings setup, long expected_steps,
                     std::function<void(const RunWarning&)> say)
    : spec_(spec),
      warnings_(std::move(setup.warnings)),
      say_(std::move(say)),
      energy_{WarningKind::energy_error, spec.energy_error_warning},
      penetration_{WarningKind::penetration, spec.penetration_warning},
      motion_{WarningKind::contact_motion, spec.contact_motion_warning},
      one_point_{WarningKind::unsafe_choice, one_point_penetration},
      one_point_contact_(std::move(setup.one_point_contact)) {
  warnings_.reserve(warnings_.size() + 8);  // the run-time kinds, each at most once
  if (spec_.quasi_static) {
    sustained_steps_ = std::max(1L, static_cast<long>(std::ceil(sustained_fraction * double(expected_steps))));
    stride_ = std::max(1L, expected_steps / target_samples);
    capacity_ = sample_width * 2 * static_cast<std::size_t>(target_samples);
    samples_.reserve(capacity_);
  }
}

void RunGuards::watch(Watch& w, long step, double t, double value, int node) {
  if (!(value > w.threshold)) return;
  if (w.entry < 0) {
    RunWarning r;
    r.kind = w.kind;
    r.step = r.max_step = step;
    r.time = r.max_time = t;
    r.value = r.max_value = value;
    r.threshold = w.threshold;
    r.node = node;
    r.message = text(r);
    w.entry = static_cast<int>(warnings_.size());
    warnings_.push_back(std::move(r));
    say_(warnings_.back());
    return;
  }
  RunWarning& r = entry(w);
  if (value > r.max_value) {
    r.max_value = value;
    r.max_step = step;
    r.max_time = t;
  }
}

void RunGuards::observe(long step, double t, const Energies& energies, const contact::ContactTotals* contact,
                        double translational_kinetic) {
  if (step > 0) {
    const double error = energies.relative_error();
    watch(energy_, step, t, error, -1);
    if (spec_.energy_error_limit && error > *spec_.energy_error_limit)
      throw NumericalFailure(format("energy error %.3g exceeds the limit %.3g of the deck at step %ld, t = %.6g s",
                                    error, *spec_.energy_error_limit, step, t));
  }
  if (contact) {
    watch(penetration_, step, t, contact->max_penetration_ratio, contact->penetration_node);
    if (!one_point_contact_.empty()) watch(one_point_, step, t, contact->max_penetration_ratio, contact->penetration_node);
    watch(motion_, step, t, contact->motion_ratio, contact->motion_node);
    if (contact->motion_ratio > spec_.contact_motion_limit)
      throw NumericalFailure(format("contact surfaces moved %.3g capture distances in one step (node %d) at step %ld, "
                                    "t = %.6g s, past 'contact motion limit' %.3g: a body can pass through the other "
                                    "unseen (tunnelling); drive slower, lower 'time step scale factor' or raise "
                                    "'search margin'",
                                    contact->motion_ratio, contact->motion_node + 1, step, t,
                                    spec_.contact_motion_limit));
  }
  if (wants_sample(step)) {
    if (samples_.size() + sample_width > capacity_) {
      // Full: keep every other sample and halve the rate (no allocation).
      const std::size_t rows = samples_.size() / sample_width;
      for (std::size_t i = 0; 2 * i < rows; ++i)
        std::copy_n(samples_.begin() + static_cast<long>(2 * i * sample_width), sample_width,
                    samples_.begin() + static_cast<long>(i * sample_width));
      samples_.resize(((rows + 1) / 2) * sample_width);
      stride_ *= 2;
      if (step % stride_ != 0) return;
    }
    const double deformation_kinetic = std::max(0.0, energies.kinetic - translational_kinetic);
    samples_.insert(samples_.end(), {double(step), t, deformation_kinetic, energies.internal});
    if (spec_.kinetic_energy_limit) watch_sustained_kinetic(step, t, deformation_kinetic, energies.internal);
  }
}

void RunGuards::watch_sustained_kinetic(long step, double t, double kinetic, double internal) {
  running_peak_ = std::max(running_peak_, internal);
  const bool loaded = internal > 0.0 && internal >= loaded_fraction * running_peak_;
  if (!loaded || !(kinetic / internal > *spec_.kinetic_energy_limit)) {
    excess_since_ = -1;
    return;
  }
  if (excess_since_ < 0) {
    excess_since_ = step;
    excess_since_time_ = t;
  }
  if (step - excess_since_ < sustained_steps_) return;
  throw NumericalFailure(format(
      "kinetic energy (less the blocks' mean translation) is %.3g %% of internal energy at step %ld, t = %.6g s, and "
      "has been above 'maximum kinetic energy ratio' %.3g %% of 'begin mass scaling' since step %ld, t = %.6g s (%ld "
      "steps, %.0f %% of the run, where the internal energy is at least %.0f %% of its peak so far): the added mass "
      "made the run dynamic; lower the target time step, drive slower or damp",
      100 * kinetic / internal, step, t, 100 * *spec_.kinetic_energy_limit, excess_since_, excess_since_time_,
      step - excess_since_, 100 * sustained_fraction, 100 * loaded_fraction));
}

std::string RunGuards::finish() {
  const std::string failure = scan_quasi_static();
  // The messages of summary.json carry each warning's largest value.
  for (const Watch* w : {&energy_, &penetration_, &motion_, &one_point_})
    if (w->entry >= 0) entry(*w).message = text(entry(*w));
  return failure;
}

std::string RunGuards::scan_quasi_static() {
  if (!spec_.quasi_static || samples_.empty()) return {};
  double peak = 0.0;
  for (std::size_t i = 0; i < samples_.size(); i += sample_width) peak = std::max(peak, samples_[i + 3]);
  if (!(peak > 0.0)) return {};
  Watch kinetic{WarningKind::kinetic_energy, spec_.kinetic_energy_warning};
  const auto quiet = std::move(say_);  // print once, with its maximum, after the scan
  say_ = [](const RunWarning&) {};
  for (std::size_t i = 0; i < samples_.size(); i += sample_width) {
    const double internal = samples_[i + 3];
    if (internal < loaded_fraction * peak) continue;
    watch(kinetic, static_cast<long>(samples_[i]), samples_[i + 1], samples_[i + 2] / internal, -1);
  }
  say_ = quiet;
  if (kinetic.entry < 0) return {};
  const RunWarning& w = entry(kinetic);
  say_(w);
  // Mass-scaled runs (`maximum kinetic energy ratio`): over the same loaded window, a limit that fails the
  // run (exit 3). The window needs the whole run's peak, so the run is judged when it ends.
  if (!spec_.kinetic_energy_limit || !(w.max_value > *spec_.kinetic_energy_limit)) return {};
  return format("kinetic energy (less the blocks' mean translation) reached %.3g %% of internal energy at step %ld, "
                "t = %.6g s, above 'maximum kinetic energy ratio' %.3g %% of 'begin mass scaling' (checked where the "
                "internal energy is at least %.0f %% of its peak): the added mass made the run dynamic; lower the "
                "target time step, drive slower or damp",
                100 * w.max_value, w.max_step, w.max_time, 100 * *spec_.kinetic_energy_limit, 100 * loaded_fraction);
}

void RunGuards::save(StateArchive& archive) const {
  std::vector<double> flat;
  for (const Watch* w : {&energy_, &penetration_, &motion_, &one_point_}) {
    if (w->entry < 0) continue;
    append_stored(warning_fields(), warnings_[static_cast<std::size_t>(w->entry)], flat);
  }
  archive.put("guards_warnings", flat);
  archive.put("guards_samples", samples_);
  archive.put("guards_stride", double(stride_));
  // The mid-run kinetic-energy stop: peak internal energy so far (J), start step and time (s) of the excess.
  archive.put("guards_kinetic_excess", std::vector<double>{running_peak_, double(excess_since_), excess_since_time_});
}

void RunGuards::restore(const StateArchive& archive) {
  if (!archive.has("guards_warnings")) return;  // a restart file of an earlier tribex: start afresh
  // The warnings' stored fields, one run of warning_fields() after the other; the message is made again.
  const auto& flat = archive.array("guards_warnings");
  const std::size_t width = stored_count(warning_fields());
  if (flat.size() % width != 0)
    throw SetupError("restart file: the guards' warnings hold " + std::to_string(flat.size()) +
                     " values, not a multiple of the " + std::to_string(width) + " this tribex keeps per warning");
  for (std::size_t i = 0; i < flat.size(); i += width) {
    RunWarning r;
    restore_stored(warning_fields(), flat.data() + i, r);
    r.message = text(r);
    for (Watch* w : {&energy_, &penetration_, &motion_, &one_point_})
      if (w->kind == r.kind) w->entry = static_cast<int>(warnings_.size());
    warnings_.push_back(std::move(r));
  }
  samples_ = archive.array("guards_samples");
  samples_.reserve(std::max(capacity_, samples_.size()));
  capacity_ = std::max(capacity_, samples_.capacity());
  stride_ = static_cast<long>(archive.scalar("guards_stride"));
  if (archive.has("guards_kinetic_excess")) {
    const auto& peak = archive.array("guards_kinetic_excess");
    if (peak.size() != 3)
      throw SetupError("restart file: 'guards_kinetic_excess' holds " + std::to_string(peak.size()) +
                       " values, not the 3 this tribex keeps");
    running_peak_ = peak[0];
    excess_since_ = static_cast<long>(peak[1]);
    excess_since_time_ = peak[2];
  }
}

}  // namespace tribex::solver
