// SPDX-License-Identifier: MIT
// run_deck, stages 4-5 (deck_run.hpp): the loop, what it writes at time n (history row, fields,
// restart file, progress), and the close (summary.json, the closing lines).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>

#include "solver/run/deck_run.hpp"
#include "solver/output/rigid_body_history.hpp"
#include "solver/errors.hpp"
#include "solver/run/mpirun_grace.hpp"
#include "solver/output/summary_writer.hpp"
#include "solver/restart/run_fingerprint.hpp"

namespace tribex::solver {
namespace {

std::string human_seconds(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 120) return format("%.0f s", s);
  if (s < 7200) return format("%.1f min", s / 60);
  return format("%.1f h", s / 3600);
}

}  // namespace

void DeckRun::write_restart() {
  StateArchive archive;
  integrator_->save_state(archive);
  guards_->save(archive);
  archive.put_integers("deck_text", as_codes(deck_.resolved_text));
  archive.put_integers("mesh_sha256", as_codes(mesh_hash_));
  archive.put("history_next", history_schedule_->next());
  archive.put("results_next", field_schedule_ ? field_schedule_->next() : 0.0);
  archive.put("run_wall_seconds", earlier_wall_seconds_ + seconds_since(wall_start_));
  archive.put("run_loop_seconds", earlier_loop_seconds_ + seconds_since(loop_start_));
  const std::string file = restart_output_->write(archive);
  log_.record(format("restart file %s at step %ld, t = %.9g s\n", file.c_str(), integrator_->step_index(), integrator_->time()));
}

std::string DeckRun::progress_text(long n, double t, double error) const {
  const double span = tc_.termination_time - tc_.start_time;
  const double frac = span > 0 ? (t - tc_.start_time) / span : 1.0;
  // The rate of this process's loop: a resumed run has covered only t - loop_start_time_ in `elapsed`.
  const double elapsed = seconds_since(loop_start_), covered = t - loop_start_time_;
  return format("step %ld | t %.4g s | %5.1f%% | ETA %s | dt %.3g s | energy error %.2e", n, t, 100.0 * frac,
                human_seconds(covered > 0 ? elapsed * (tc_.termination_time - t) / covered : NAN).c_str(), integrator_->dt(),
                error);
}

void DeckRun::fill_history_row(double t) {
  const HistoryState state{t,
                           integrator_->dt(),
                           integrator_->energies(),
                           integrator_->contact_totals(),
                           integrator_->momentum(),
                           model_->mass_scaling.added_mass};
  row_.clear();
  for (const HistoryColumn& c : history_columns())
    if (c.present(material_dissipation_, model_->mass_scaling.active)) row_.push_back(c.value(state));
  std::fill(set_sums_.begin(), set_sums_.end(), 0.0);
  std::size_t c = 0;
  for (const auto& set : reaction_sets_) {
    for (int node : set)
      for (int i = 0; i < 3; ++i) set_sums_[c + i] += integrator_->reaction()[3 * node + i];
    c += 3;
  }
  for (const auto& set : displacement_sets_) {
    for (int node : set)
      for (int i = 0; i < 3; ++i) set_sums_[c + i] += integrator_->displacement()[3 * node + i];
    c += 3;
  }
  parallel::sum(set_sums_.data(), static_cast<int>(set_sums_.size()));
  for (std::size_t k = 0; k < displacement_sets_.size(); ++k)
    for (int i = 0; i < 3; ++i) set_sums_[3 * (reaction_sets_.size() + k) + i] /= displacement_set_size_[k];
  row_.insert(row_.end(), set_sums_.begin(), set_sums_.end());
  if (!rigid_values_.empty()) {
    rigid_body_history_values(*model_, {t, integrator_->displacement().data(), integrator_->reaction().data(),
                                        integrator_->rigid_coupling_force().data(), &integrator_->rigid_motion()},
                              rigid_values_);
    row_.insert(row_.end(), rigid_values_.begin(), rigid_values_.end());
  }
}

void DeckRun::write_history_row(double t, long n) {
  fill_history_row(t);
  if (history_) history_->write_row(n, row_);
}

void DeckRun::write_fields(double t, long n) {
  // The deck's fields from the table (inputs/result_fields.hpp), this rank's rows of each.
  field_source_->start_output();
  nodal_views_.clear();
  element_views_.clear();
  collect_fields(region_.results->nodal_variables, inputs::FieldKind::nodal, *field_source_, nodal_views_);
  collect_fields(region_.results->element_variables, inputs::FieldKind::element, *field_source_, element_views_);
  const auto& nodal = nodal_views_;
  const auto& element = element_views_;
  if (results_) results_->write_step(t, nodal, element);
  if (exodus_) {
    fill_history_row(t);  // every rank: the node-set columns are sums over the ranks
    globals_.clear();
    globals_.push_back(static_cast<double>(n));
    globals_.insert(globals_.end(), row_.begin(), row_.end());
    exodus_->write_step(t, nodal, element, globals_);
  }
}

void DeckRun::write_output_step(double t, long n, bool history_due, bool fields_due) {
  // A write that fails on some ranks only (history.csv is rank 0's; a full disk may fail one rank's
  // share of a collective write) must stop every rank at this step: the others would otherwise wait in
  // the next collective call for a rank that has left the loop (a 2-rank run into a full tmpfs hung).
  // So each rank finishes the step's collective calls, then the ranks agree before anyone throws.
  std::string failure;
  try {
    if (history_due) {
      write_history_row(t, n);
      history_schedule_->done(t);
    }
  } catch (const OutputError& e) {
    failure = e.what();
  }
  try {
    if (fields_due) {
      write_fields(t, n);
      field_schedule_->done(t);
    }
  } catch (const OutputError& e) {
    if (failure.empty()) failure = e.what();
  }
  const bool failed = ranks_ > 1 ? parallel::max(failure.empty() ? 0LL : 1LL) != 0 : !failure.empty();
  if (failed)
    throw OutputError(!failure.empty() ? failure
                                       : "another rank could not write its outputs at step " + std::to_string(n) +
                                             " (rank 0's log.txt and summary.json name the file)");
}

void DeckRun::write_outputs() {
  const double t = integrator_->time();
  const long n = integrator_->step_index();
  const auto& E = integrator_->energies();
  const bool history_due = history_schedule_->due(t, n, closing_);
  const bool fields_due = field_schedule_ && field_schedule_->due(t, n, closing_);
  if (history_due || fields_due) write_output_step(t, n, history_due, fields_due);
  guards_->observe(n, t, E, model_->contact ? &integrator_->contact_totals() : nullptr,
                   guards_->wants_sample(n) ? block_translation_->kinetic_energy(integrator_->velocity()) : 0.0);
  if (strain_guard_->due(n) && n > 0) {
    const StrainPeak peak = strain_guard_->peak(model_->blocks);
    guards_->observe_strain(n, t, peak.value, peak.element, peak.block);
  }
  if (terminal_ && seconds_since(last_progress_) > 0.5) {
    last_progress_ = Clock::now();
    std::fprintf(stderr, "\r  %s   ", progress_text(n, t, E.relative_error()).c_str());
    std::fflush(stderr);
  }
  if (heartbeat_ && seconds_since(last_heartbeat_) >= options_.heartbeat_seconds) {
    last_heartbeat_ = Clock::now();
    log_.say("heartbeat: " + progress_text(n, t, E.relative_error()));
  }
}

void DeckRun::loop() {
  const double end_time = tc_.termination_time;
  integrator_->set_stress_request([this, end_time](double t, long n) {
    return (field_schedule_ && !region_.results->element_variables.empty() &&
            field_schedule_->due(t, n, t >= end_time * (1 - 1e-14))) ||
           strain_guard_->due(n);
  });
  row_.reserve(history_columns_.size());
  globals_.reserve(history_columns_.size());
  field_source_.emplace(*model_, *integrator_, surface_index_);
  terminal_ = root_ && !options_.quiet && isatty(STDERR_FILENO);
  // Batch jobs and pipes get a heartbeat line instead of the terminal's carriage-return progress.
  // Parallel runs always do: Open MPI gives the ranks a pseudo-terminal for stdout whatever mpiexec's
  // own stdout is, so rank 0 cannot tell a terminal from a batch job's file (measured: a 2-rank run
  // redirected to a file printed nothing for 8 minutes).
  heartbeat_ = root_ && options_.heartbeat_seconds > 0 && (ranks_ > 1 || !isatty(STDOUT_FILENO));
  last_progress_ = last_heartbeat_ = Clock::now();

  fault_signal_point("outputs");
  const std::function<void()> on_time_n = [this] { write_outputs(); };  // built once: no allocation per step
  contact_seconds_before_ = integrator_->contact_seconds();
  log_.say("running ...");
  loop_start_ = Clock::now();
  loop_start_time_ = integrator_->time();
  bool stopped_at_step = false;
  try {
    if (!resume_) integrator_->init();
    while (!integrator_->finished()) {
      integrator_->step(on_time_n);
      // The added-mass guard (solver/setup/mass_scaling.hpp): stop after the first step, whose step writes
      // the t = 0 outputs (history row, fields), so the files are valid.
      if (model_->mass_scaling.exceeds_limit()) throw NumericalFailure(model_->mass_scaling.limit_message());
      stopped_at_step = options_.stop_at_step >= 0 && integrator_->step_index() >= options_.stop_at_step;
      // Every rank stops at the same step, for the signal any of them received (the largest number).
      long long signal = stop_signal();
      if (ranks_ > 1) signal = parallel::max(signal);
      const bool stop = signal != 0 || stopped_at_step;
      if (signal != 0) {
        stopped_by_signal_ = true;
        stop_seen_ = Clock::now();
        log_.say(format("stopping after step %ld: %s", integrator_->step_index(),
                        stop_signal_text(static_cast<int>(signal)).c_str()));
      }
      if (restart_output_ && (stop || restart_output_->due(integrator_->step_index()))) write_restart();
      if (stop) break;
    }
    closing_ = true;
    integrator_->close(on_time_n);
    const bool interrupted = stopped_by_signal_ || stopped_at_step;
    summary_.exit_code = interrupted ? 130 : 0;
    summary_.status = interrupted ? "interrupted" : "normal termination";
  } catch (const NumericalFailure& e) {
    summary_.exit_code = 3;
    summary_.status = std::string("numerical failure: ") + e.what();
  } catch (const OutputError& e) {
    summary_.exit_code = 3;
    summary_.status = std::string("output failure: ") + e.what();
  } catch (const std::bad_alloc&) {
    // The failed request is freed; what the close needs (summary.json, a few KB) is small.
    summary_.exit_code = 3;
    summary_.status = out_of_memory_text(format("running step %ld", integrator_->step_index() + 1)) +
                      "; the files up to the last complete output step are kept";
  }
  summary_.loop_seconds = seconds_since(loop_start_);
  if (terminal_) std::fprintf(stderr, "\n");
}

void DeckRun::close() {
  RunSummary& summary = summary_;
  const std::string guard_failure = guards_->finish();
  if (!guard_failure.empty() && (summary.exit_code == 0 || summary.exit_code == 130)) {
    summary.exit_code = 3;
    summary.status = "numerical failure: " + guard_failure;
  }
  summary.warnings = guards_->warnings();
  try {
    if (results_) results_->flush();  // collective in a parallel run: every rank gets here
    if (exodus_) exodus_->flush();
  } catch (const OutputError& e) {
    if (summary.exit_code == 0 || summary.exit_code == 130) {
      summary.exit_code = 3;
      summary.status = std::string("output failure: ") + e.what();
    }
  } catch (const std::bad_alloc&) {
    if (summary.exit_code == 0 || summary.exit_code == 130) {
      summary.exit_code = 3;
      summary.status = out_of_memory_text("closing the results files");
    }
  }
  summary.steps = integrator_->step_index();
  summary.first_step = first_step_;
  summary.total_wall_seconds = earlier_wall_seconds_ + seconds_since(wall_start_);
  summary.total_loop_seconds = earlier_loop_seconds_ + summary.loop_seconds;
  summary.contact_seconds = integrator_->contact_seconds();
  summary.ranks = ranks_;
  summary.communication_seconds = model_->domain.communication_seconds;
  if (model_->contact) summary.contact_balance = model_->contact->work().balance(ranks_);
  summary.final_time = integrator_->time();
  summary.energy_error = integrator_->energies().relative_error();
  summary.energies = integrator_->energies();
  summary.initial_stable_time_step = stable0_.dt;
  summary.controlling_element = stable0_.controlling_element;
  summary.mass_scaling = model_->mass_scaling;
  // Collective (every rank reaches the close): each rank's counts to rank 0.
  summary.rank_counts = parallel::gather_rank_counts(
      parallel::count_rank(*model_, region_.contact ? &*region_.contact : nullptr, peak_rss_setup_));
  const long steps_run = summary.steps - summary.first_step;  // by this process
  summary.ns_per_element_step =
      steps_run > 0 && elements_ > 0 ? 1e9 * summary.loop_seconds / (double(elements_) * double(steps_run)) : 0.0;
  summary.wall_seconds = seconds_since(wall_start_);
  if (root_) {
    try {
      write_summary_json((out_ / "summary.json").string(), summary);
    } catch (const std::exception& e) {  // a full disk: say so; the status still ends the log and stderr
      std::fprintf(stderr, "error: %s\n", e.what());
      if (summary.exit_code == 0) {
        summary.exit_code = 3;
        summary.status = std::string("output failure: ") + e.what();
      }
    }
  }
  if (stopped_by_signal_) {
    // From the signal's arrival on the rank that had it longest: the step then running is included.
    const double took = parallel::max(std::max(seconds_since_stop_signal(), seconds_since(stop_seen_)));
    log_.say(format("stop: the step, the restart file, the outputs and summary.json written %.3g s after the signal", took));
    const std::string note = mpirun_stop_grace_note(took, "measured");
    if (!note.empty()) log_.say(note);
  }
  close_log_lines();
}

void DeckRun::close_log_lines() {
  const RunSummary& summary = summary_;
  const long steps_run = summary.steps - summary.first_step;
  log_.say(format("%ld steps to t = %.6g s in %.3g s wall (loop %.3g s, %.1f ns per element per step); energy error %.3e",
                  steps_run, summary.final_time, summary.wall_seconds, summary.loop_seconds,
                  summary.ns_per_element_step, summary.energy_error));
  if (summary.first_step > 0 && std::isfinite(summary.total_wall_seconds))
    log_.say(format("resumed at step %ld: the whole run, %ld steps, took %.4g s wall (loop %.4g s) over its segments",
                    summary.first_step, summary.steps, summary.total_wall_seconds, summary.total_loop_seconds));
  else if (summary.first_step > 0)
    log_.say(format("resumed at step %ld: the whole run's time is unknown (an earlier segment's restart file did not "
                    "record it; add the segments' wall times in log.txt)", summary.first_step));
  const std::string exodus_files = !exodus_ ? "" : ranks_ == 1 ? ",results.exo" : format(",results.exo.%d.*", ranks_);
  log_.say(format("outputs: %s/{history.csv,summary.json,log.txt%s%s}", out_.string().c_str(),
                  results_ ? ",results.h5,results.xdmf" : "", exodus_files.c_str()));
  if (exodus_ && ranks_ > 1)  // one Exodus file per rank (output/README.md "Exodus II output")
    log_.say(format("results.exo: one file per rank, which ParaView opens as one data set (open results.exo.%d.0); "
                    "`tribex join %s` writes the one results.exo", ranks_, out_.string().c_str()));
  if (model_->contact) {
    const double segment_contact_seconds = summary.contact_seconds - contact_seconds_before_;
    log_.say(format("contact: %.3g s of the loop (%.1f %%), %ld broad-phase searches", segment_contact_seconds,
                    summary.loop_seconds > 0 ? 100.0 * segment_contact_seconds / summary.loop_seconds : 0.0,
                    model_->contact->total_searches()));
    if (ranks_ > 1) {
      // A zone on one rank at a time (one that travels across the partition's cuts) leaves the others
      // waiting: say so with the remedy. 0.75 x ranks: most of the work on one rank.
      const bool lopsided = summary.contact_balance > 0.75 * ranks_;
      log_.say(format("contact: the busiest rank evaluated %.2fx the even share of the candidate pairs%s",
                      summary.contact_balance,
                      lopsided ? "; the contact zone lay on few ranks: a zone that travels stays shared when the "
                                 "partition's cuts run along its path (begin decomposition, docs/deck_reference.md)"
                               : ""));
    }
  }
  if (ranks_ > 1) {
    // Waiting at the exchange is most of it: the rank that waits least carries the most work.
    const double share = summary.loop_seconds > 0 ? 100.0 * summary.communication_seconds / summary.loop_seconds : 0.0;
    const double least = parallel::min(share), most = parallel::max(share);
    log_.say(format("parallel: %d ranks; rank 0 spent %.3g s of the loop (%.1f %%) in communication, waits included "
                    "(%.1f-%.1f %% over the ranks)",
                    ranks_, summary.communication_seconds, share, least, most));
  }
  std::string closing_line = summary.exit_code == 0 ? "Normal termination" : "Error termination: " + summary.status;
  if (!summary.warnings.empty()) {
    std::string kinds;
    for (const auto& w : summary.warnings) kinds += (kinds.empty() ? "" : ", ") + std::string(kind_name(w.kind));
    closing_line += format(" (%zu warning%s: %s; see summary.json)", summary.warnings.size(),
                           summary.warnings.size() == 1 ? "" : "s", kinds.c_str());
  }
  log_.say(closing_line);
  // --quiet silences the terminal, not the reason a run failed: that still goes to stderr.
  if (summary.exit_code != 0 && root_ && options_.quiet) std::fprintf(stderr, "%s\n", closing_line.c_str());
}

}  // namespace tribex::solver
