// SPDX-License-Identifier: MIT
#include "solver/guards/run_guards.hpp"

#include <algorithm>
#include <cmath>

#include "solver/errors.hpp"
#include "solver/guards/strain_guard.hpp"
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
    case WarningKind::large_strain: return "large_strain";
    case WarningKind::scaled_silent_boundary: return "scaled_silent_boundary";
  }
  return "unknown";
}

const char* source_name(EnergySource source) {
  switch (source) {
    case EnergySource::none: return "";
    case EnergySource::contact: return "contact_work";
    case EnergySource::hourglass: return "hourglass_energy";
    case EnergySource::viscous: return "viscous_dissipation";
    case EnergySource::damping: return "damping_dissipation";
    case EnergySource::silent_boundary: return "silent_boundary_dissipation";
    case EnergySource::plastic: return "plastic_dissipation";
    case EnergySource::kinetic: return "kinetic_energy";
  }
  return "";
}

namespace {

// The energy warning's likely source in words, with what to change (solver/guards/README.md).
std::string source_text(const RunWarning& w, const WarningContext& c) {
  const std::string since = format("since step %ld", w.since_step);
  switch (w.source) {
    case EnergySource::none:
      return "see contact_work and the dissipation columns of history.csv";
    case EnergySource::contact:
      return format("likely source: the contact (interaction %s) gave %.3g J to the bodies %s (contact_work fell): "
                    "contact nodes chatter or snap through; ",
                    c.contact_interactions.c_str(), w.source_change, since.c_str()) +
             (c.mass_scaled ? "with mass scaling compare the unscaled run and lower 'largest factor' (the contact "
                              "surfaces' mass raise is in log.txt); "
                            : "") +
             "lower 'penalty scale factor', refine the contact surfaces or use 'enforcement = mortar'";
    case EnergySource::hourglass:
      return format("likely source: hourglass energy grew %.3g J %s: hourglass modes of one-point (mean_quadrature) "
                    "elements; use 'formulation = fully_integrated' where the load is concentrated",
                    w.source_change, since.c_str());
    case EnergySource::viscous:
      return format("likely source: bulk and hourglass viscosity dissipated %.3g J %s: a high-frequency ring (contact "
                    "chatter, a shock or an abrupt drive); smooth the drive, look at contact_work",
                    w.source_change, since.c_str());
    case EnergySource::damping:
      return format("likely source: mass damping dissipated %.3g J %s: check 'mass damping coefficient' against the "
                    "drive (it damps rigid motion too)",
                    w.source_change, since.c_str());
    case EnergySource::silent_boundary:
      return format("likely source: the silent boundaries absorbed %.3g J %s: check which faces carry them",
                    w.source_change, since.c_str());
    case EnergySource::plastic:
      return format("likely source: plastic dissipation grew %.3g J %s: check the yield data and the step",
                    w.source_change, since.c_str());
    case EnergySource::kinetic:
      return format("likely source: kinetic energy grew %.3g J %s%s", w.source_change, since.c_str(),
                    c.mass_scaled ? ": the added mass of 'begin mass scaling' made the run dynamic; lower the factor or "
                                    "drive slower"
                                  : ": drive slower or damp");
  }
  return "";
}

}  // namespace

std::string describe(const RunWarning& w, const WarningContext& context) {
  std::string what;
  switch (w.kind) {
    case WarningKind::energy_error:
      what = format("energy balance error %.3g %% at %s is above 'energy error warning' %.3g %%: energy is not "
                    "conserved; ",
                    100 * w.value, where(w.step, w.time).c_str(), 100 * w.threshold) +
             source_text(w, context);
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
                    w.value, w.node + 1, where(w.step, w.time).c_str(), context.one_point_contact.c_str());
      break;
    case WarningKind::large_strain: {
      const auto& names = context.block_names;
      const std::string block = w.block >= 0 && w.block < static_cast<int>(names.size())
                                    ? names[static_cast<std::size_t>(w.block)] : std::string("?");
      what = format("block '%s' (small-strain elastic) reached a principal strain of %.3g at element %d, %s, above %.3g: "
                    "the small-strain law is accurate, and rotation-invariant, only for small strains; give the block's "
                    "material 'begin parameters for model neo_hookean' (finite strain)",
                    block.c_str(), w.value, w.node + 1, where(w.step, w.time).c_str(), w.threshold);
      break;
    }
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
      strain_{WarningKind::large_strain, small_strain_warning},
      context_{std::move(setup.one_point_contact), std::move(setup.contact_interactions), setup.mass_scaled,
               std::move(setup.block_names)} {
  warnings_.reserve(warnings_.size() + 8);  // the run-time kinds, each at most once
  if (spec_.quasi_static) {
    sustained_steps_ = std::max(1L, static_cast<long>(std::ceil(sustained_fraction * double(expected_steps))));
    stride_ = std::max(1L, expected_steps / target_samples);
    capacity_ = sample_width * 2 * static_cast<std::size_t>(target_samples);
    samples_.reserve(capacity_);
  }
}

void RunGuards::observe_strain(long step, double t, double value, int element, int block) {
  watch(strain_, step, t, value, element, block);
}

void RunGuards::watch(Watch& w, long step, double t, double value, int node, int block) {
  if (!(value > w.threshold)) return;
  if (w.entry < 0) {
    RunWarning r;
    r.kind = w.kind;
    r.step = r.max_step = step;
    r.time = r.max_time = t;
    r.value = r.max_value = value;
    r.threshold = w.threshold;
    r.node = node;
    r.block = block;
    if (w.kind == WarningKind::energy_error && observed_) attribute(*observed_, r);
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

// The term of the ledger that changed most since the error was last below half the warning, among those
// that carry energy out of the balance's conservative part (contact, hourglass, the dissipations) and the
// kinetic energy. The contact is named first when it gave the bodies energy (contact_work fell) by at least a
// quarter of the largest change: an elastic penalty contact only stores k g^2 / 2 >= 0 (plus the adhesion
// energy, which a chattering contact does not release), so a falling contact_work means injection, and the
// viscosity that takes the resulting ring out appears beside it (issue 51: -2.7e-19 J and +2.8e-19 J).
void RunGuards::attribute(const Energies& now, RunWarning& w) const {
  const Energies& c = clean_;
  const std::pair<EnergySource, double> changes[] = {
      {EnergySource::contact, c.contact_work - now.contact_work},
      {EnergySource::hourglass, now.hourglass - c.hourglass},
      {EnergySource::viscous, now.viscous_dissipation - c.viscous_dissipation},
      {EnergySource::damping, now.damping_dissipation - c.damping_dissipation},
      {EnergySource::silent_boundary, now.silent_boundary_dissipation - c.silent_boundary_dissipation},
      {EnergySource::plastic, now.plastic_dissipation - c.plastic_dissipation},
      {EnergySource::kinetic, now.kinetic - c.kinetic},
  };
  double largest = 0.0;
  for (const auto& [source, change] : changes) largest = std::max(largest, std::abs(change));
  w.since_step = clean_step_;
  if (!(largest > 0.0)) return;
  const double contact_gave = changes[0].second;
  const bool contact_injected = !context_.contact_interactions.empty() && contact_gave >= 0.25 * largest;
  const auto& [source, change] =
      contact_injected ? changes[0]
                       : *std::max_element(std::begin(changes), std::end(changes), [](const auto& a, const auto& b) {
                           return std::abs(a.second) < std::abs(b.second);
                         });
  w.source = source;
  w.source_change = change;
}

void RunGuards::observe(long step, double t, const Energies& energies, const contact::ContactTotals* contact,
                        double translational_kinetic) {
  if (step > 0) {
    const double error = energies.relative_error();
    observed_ = &energies;
    watch(energy_, step, t, error, -1);
    observed_ = nullptr;
    if (!(error > 0.5 * energy_.threshold)) {
      clean_ = energies;
      clean_step_ = step;
    }
    if (spec_.energy_error_limit && error > *spec_.energy_error_limit)
      throw NumericalFailure(format("energy error %.3g exceeds the limit %.3g of the deck at step %ld, t = %.6g s",
                                    error, *spec_.energy_error_limit, step, t));
  }
  if (contact) {
    watch(penetration_, step, t, contact->max_penetration_ratio, contact->penetration_node);
    if (!context_.one_point_contact.empty()) watch(one_point_, step, t, contact->max_penetration_ratio, contact->penetration_node);
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
  for (const Watch* w : {&energy_, &penetration_, &motion_, &one_point_, &strain_})
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
  for (const Watch* w : {&energy_, &penetration_, &motion_, &one_point_, &strain_}) {
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
    for (Watch* w : {&energy_, &penetration_, &motion_, &one_point_, &strain_})
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
