// SPDX-License-Identifier: MIT
// The stages of run_deck (solver/run/run.hpp), private to solver/: deck_run_setup.cpp holds pre-flight,
// the rank's part and the restart state, and the output files; deck_run_loop.cpp the loop, what it
// writes at time n, and the close.
#pragma once

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/parallel/contact_travel.hpp"
#include "solver/parallel/source_parts.hpp"
#include "solver/guards/block_translation.hpp"
#include "solver/guards/run_guards.hpp"
#include "solver/guards/strain_guard.hpp"
#include "solver/integrators/central_difference.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "solver/run/out_of_memory.hpp"
#include "solver/output/exodus_writer.hpp"
#include "solver/output/field_source.hpp"
#include "solver/output/history_writer.hpp"
#include "solver/output/output_folder.hpp"
#include "solver/output/results_writer.hpp"
#include "solver/output/run_log.hpp"
#include "solver/output/schedule.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/rank_counts.hpp"
#include "solver/restart/restart_output.hpp"
#include "solver/restart/state_archive.hpp"
#include "solver/run/run.hpp"
#include "solver/run/stop_signal.hpp"

namespace tribex::solver {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// One run of a deck, in its stages: pre-flight (the whole model, checked and reported), the
/// rank's part and the restart state, the output files, the loop, the close (summary.json and the
/// closing lines). What the stages share is kept here; the loop allocates nothing.
class DeckRun {
 public:
  DeckRun(const inputs::Deck& deck, const RunOptions& options)
      : deck_(deck), options_(options), region_(deck.procedure.region), tc_(deck.procedure.time_control),
        root_(parallel::is_root()), ranks_(parallel::size()), log_(options.quiet || !root_) {}

  RunSummary run() {
    set_up("building the model", [this] { preflight(); });
    if (options_.check_only) {
      summary_.status = "checked";
      return summary_;
    }
    set_up("reading the restart state", [this] { start_from_restart(); });
    stop_before_outputs("before the output files were opened");
    set_up("claiming the output folder", [this] { claim_output_folder(); });
    set_up("opening the output files", [this] { open_outputs(); });
    peak_rss_setup_ = parallel::peak_rss_bytes();  // set-up's high-water mark, before the loop adds to it
    try {
      loop();  // its steps catch their own failures; this: the loop's buffers (fields, rows), before step 1
    } catch (const std::bad_alloc&) {
      summary_.exit_code = 3;
      summary_.status = out_of_memory_text("allocating the loop's output buffers");
    }
    close();
    return summary_;
  }

 private:
  // ---- stage 1: the model (a parallel run: this rank's part), checked and reported; nothing written ----
  void preflight();
  void build_parts();  // parallel: the whole mesh on rank 0, partitioned; every rank builds its part
  // `set-up = distributed` (`method = auto`: from `at_least` elements): false, and the log says why, if the
  // mesh is to be made on rank 0 instead
  bool build_parts_distributed(int at_least = 0);
  bool distributed_contact(const parallel::ElementSource& source, ContactFaces& contact,
                           std::optional<ContactTravel>& travel, parallel::AxisScale& scale,
                           std::optional<inputs::ContactSpec>& enforced, std::string& why);  // false: why
  void finish_distributed_parts(const parallel::ElementSource& source, parallel::SourcePart& g,
                                const parallel::AxisScale& scale, const std::optional<ContactTravel>& travel,
                                double seconds);  // check, hash, report, outline, set sizes
  void report_distributed_partition(const parallel::MeshPart& mine, long long shared, const parallel::AxisScale& scale,
                                    const std::optional<ContactTravel>& travel, double seconds, const char* each_rank);
  void report_partition(const mesh::Mesh& whole, const std::vector<int>& part, const parallel::NodeHolders& holders,
                        const parallel::AxisScale& scale, const std::optional<ContactTravel>& travel, double seconds);
  void report_mesh(const Model& model);
  // ---- stage 2: the integrator and the restart state ----
  void start_from_restart();
  // ---- stage 3: the output folder, history.csv, results.h5, restart output ----
  void claim_output_folder();  // every check, the lock, the manifest, the earlier run's files removed (rank 0)
  std::vector<std::string> deck_input_files() const;
  void report_output_folder();  // log.txt: a stale lock taken over, files removed or kept
  void open_outputs();
  void choose_history_columns();
  void note_mpirun_signal_grace();  // the Open MPI kill delay that can cost a signalled run its restart file
  void open_results();  // results.h5 + results.xdmf and/or results.exo (`format`)
  ResultsMeshRows results_mesh_rows() const;  // parallel: this rank's rows of results.h5's mesh
  // ---- stage 4: the loop and what it writes at time n ----
  void loop();
  void write_outputs();
  void fill_history_row(double t);  // row_: the history columns after `step` (collective in parallel)
  void write_history_row(double t, long n);
  void write_fields(double t, long n);
  void write_output_step(double t, long n, bool history_due, bool fields_due);
  void write_restart();
  std::string progress_text(long n, double t, double error) const;
  // ---- stage 5: summary.json and the closing lines ----
  void close();
  void close_log_lines();

  /// A set-up stage: out of memory or a full disk here is exit 2 (a SetupError naming the stage and the
  /// size, or the free space), not an internal error or a loop's exit 3; nothing has run yet.
  template <class F>
  void set_up(const char* stage, F&& body) {
    try {
      body();
    } catch (const std::bad_alloc&) {
      const std::string model = elements_ > 0 ? " for a model of " + std::to_string(elements_) + " elements" : "";
      throw SetupError(out_of_memory_text(stage) + model + "; run on more ranks (mpirun -np N), on a machine with more memory, or a coarser mesh");
    } catch (const OutputError& e) {
      std::string what = e.what();  // nothing of the run's is kept: the loop's closing words go
      what = what.substr(0, what.find("; the files up to the last complete output step are kept"));
      throw SetupError("cannot set up the outputs: " + what);
    }
  }
  /// A stop that arrives before the outputs exist ends the run here, with nothing written (every
  /// rank at the same point): set-up is not interrupted half-way.
  void stop_before_outputs(const char* stage) {
    int stop = stop_signal();
    if (ranks_ > 1) stop = static_cast<int>(parallel::max(static_cast<long long>(stop)));
    if (stop && !options_.check_only)
      throw Interrupted(std::string("interrupted during set-up (") + stage + "); nothing was written");
  }
  /// Warnings go to stderr too when the terminal is otherwise quiet.
  void announce(const RunWarning& w) {
    log_.say("warning: " + w.message);
    if (root_ && options_.quiet) std::fprintf(stderr, "warning: %s\n", w.message.c_str());
  }

  const inputs::Deck& deck_;
  const RunOptions& options_;
  const inputs::RegionSpec& region_;
  const inputs::TimeControlSpec& tc_;
  const Clock::time_point wall_start_ = Clock::now();
  const bool root_;
  const int ranks_;
  RunLog log_;  // printed once, by rank 0
  RunSummary summary_;

  // stage 1
  StableStep stable0_;
  double est_steps_ = 0.0;
  int elements_ = 0;
  std::optional<Model> model_;
  inputs::DecompositionSpec::Method method_ = inputs::DecompositionSpec::Method::metis;  // the one used (auto resolved)
  std::optional<output::MeshOutline> results_outline_;  // parallel runs with results output: the whole mesh's outline
  std::map<std::string, double> set_size_;  // node-set sizes of the whole mesh
  std::string mesh_hash_;                   // of the whole mesh (restart files)
  std::string restart_run_id_;              // rank 0: the run id the restart file carries ("" none or legacy)
  // stage 2
  std::optional<CentralDifference> integrator_;
  std::optional<RunGuards> guards_;
  std::optional<BlockTranslation> block_translation_;
  std::optional<StrainGuard> strain_guard_;
  std::optional<StateArchive> resume_;
  // stage 3
  std::filesystem::path out_;
  std::optional<FolderClaim> folder_;  // rank 0: the lock and the manifest, held to the end of the run
  bool material_dissipation_ = false;
  std::vector<ColumnInfo> history_columns_;  // step, the standard columns present, the node-set columns
  std::optional<HistoryWriter> history_;
  std::vector<std::vector<int>> reaction_sets_, displacement_sets_;
  std::vector<double> displacement_set_size_;
  std::vector<double> set_sums_;
  std::vector<double> rigid_values_;  // nine per rigid body (output/rigid_body_history.hpp)
  std::optional<Schedule> history_schedule_;
  std::unique_ptr<ResultsWriter> results_;
  std::unique_ptr<ExodusWriter> exodus_;  // results.exo; its global variables are the history columns
  std::optional<Schedule> field_schedule_;
  ResultsSlab slab_;
  long first_step_ = 0;
  double earlier_wall_seconds_ = 0.0, earlier_loop_seconds_ = 0.0;  // segments before a restart
  std::optional<RestartOutput> restart_output_;
  // stage 4
  Clock::time_point loop_start_;
  double loop_start_time_ = 0.0;  // s of simulated time at loop_start_ (the restart time on a resume)
  bool closing_ = false;
  bool stopped_by_signal_ = false;  // agreed by the ranks: the loop stopped for a signal
  Clock::time_point stop_seen_;     // when it did (the stop's time is logged at the close)
  std::vector<double> row_;
  std::vector<double> globals_;  // results.exo: step, then row_
  std::optional<FieldSource> field_source_;           // the result fields' getters read here (write_fields)
  std::vector<FieldView> nodal_views_, element_views_;  // one output's fields
  std::vector<int> surface_index_;  // [local node] its node in the contact's numbering, -1: none (contact fields)
  bool terminal_ = false, heartbeat_ = false;
  Clock::time_point last_progress_, last_heartbeat_;
  double contact_seconds_before_ = 0.0;  // earlier segments' (restart file)
  long long peak_rss_setup_ = 0;         // bytes, getrusage at the end of set-up (summary.json rank_counts)
};

}  // namespace tribex::solver
