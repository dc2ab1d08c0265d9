// SPDX-License-Identifier: MIT
// run_deck, stages 1-3 (deck_run.hpp): pre-flight, the rank's part and the restart state, the outputs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>

#include <malloc.h>

#include "mesh/mesh_error.hpp"
#include "solver/parallel/contact_partition.hpp"
#include "solver/setup/contact_setup.hpp"
#include "solver/parallel/contact_travel.hpp"
#include "solver/run/deck_run.hpp"
#include "solver/output/rigid_body_history.hpp"
#include "solver/errors.hpp"
#include "solver/run/mpirun_grace.hpp"
#include "solver/output/summary_writer.hpp"
#include "solver/parallel/element_slabs.hpp"
#include "solver/parallel/partition.hpp"
#include "solver/restart/isolated_read.hpp"
#include "solver/restart/restart_checks.hpp"
#include "solver/restart/restart_remap.hpp"
#include "solver/restart/run_fingerprint.hpp"

namespace tribex::solver {

void DeckRun::preflight() {
  fault_signal_point("setup");
  summary_.identity = identify_run(deck_.path, ranks_);
  summary_.parameters = deck_.parameters;
  // The run id: a resumed run keeps the one of the run that wrote its restart file.
  if (root_ && !options_.restart_path.empty()) restart_run_id_ = h5_run_id(options_.restart_path);
  if (root_) summary_.identity.run_id = restart_run_id_.empty() ? new_run_id() : restart_run_id_;
  if (ranks_ > 1) parallel::broadcast(summary_.identity.run_id, 0);
  log_.say(identity_line(summary_.identity));
  if (!deck_.parameters.empty()) {  // inputs/README.md "Parameters"; summary.json "parameters"
    std::string line = "parameters:";
    for (const inputs::DeckParameter& p : deck_.parameters)
      line += format(" %s = %.10g%s%s%s", p.name.c_str(), p.value, p.unit.empty() ? "" : " ", p.unit.c_str(),
                     p.set_on_command_line ? " (--set)" : "") + (&p == &deck_.parameters.back() ? "" : ",");
    log_.say(line);
  }
  // Bad input is found here, before any file is written: one rank builds the whole model; in a
  // parallel run every rank builds its part (the same checks, an error stops every rank).
  if (ranks_ == 1) {
    model_.emplace(build_model(deck_));
    mesh_hash_ = mesh_sha256(model_->mesh);
    for (const auto& [name, nodes] : model_->mesh.node_sets) set_size_[name] = double(nodes.size());
  } else {
    build_parts();
  }
  summary_.identity.mesh_sha256 = mesh_hash_;
  const Model& model = *model_;
  report_mesh(model);
  stable0_ = whole_model_stable_time_step(model);
  log_.say(format("stable time step %.6g s (element %d controls it); scale factor %.3g => dt = %.6g s", stable0_.dt,
                  stable0_.controlling_element + 1, tc_.time_step_scale_factor,
                  std::min(stable0_.dt * tc_.time_step_scale_factor, tc_.maximum_time_step.value_or(INFINITY))));
  for (const auto& line : model.mass_scaling.lines()) log_.say(line);
  est_steps_ = (tc_.termination_time - tc_.start_time) /
               std::min(stable0_.dt * tc_.time_step_scale_factor, tc_.maximum_time_step.value_or(INFINITY));
  log_.say(format("termination time %.6g s: about %.0f steps", tc_.termination_time, std::ceil(est_steps_)));
  // Counted on the owned copies (constraints and dashpots sit on every copy of a node).
  double counts[2] = {0.0, 0.0};
  for (int dof : model.constraints.dof) counts[0] += model.domain.owned[dof / 3];
  for (int node : model.silent.node) counts[1] += model.domain.owned[node];
  parallel::sum(counts, 2);
  log_.say(format("constraints: %.0f dofs; silent-boundary nodes: %.0f; pressure loads: %zu", counts[0], counts[1],
                  model.pressures.size()));
  for (const auto& line : model.preflight) log_.say(line);
  for (const auto& w : model.setup.warnings) announce(w);
  summary_.elements = elements_;
  summary_.nodes = model.domain.global_node_count;
  // `tribex check` stops where the run would (exit 3, the same message); a run stops after its outputs
  // are open (DeckRun::loop), so that they are valid.
  if (options_.check_only && model.mass_scaling.exceeds_limit())
    throw NumericalFailure(model.mass_scaling.limit_message());
}

void DeckRun::build_parts() {
  // Rank 0 reads or generates the whole mesh, checks and partitions it (with `method = ptscotch` all
  // the ranks partition it together), and sends every rank its part, then frees the whole mesh (the
  // results writers need only its outline). With `set-up = distributed` every rank makes its own part
  // of a generated mesh instead (deck_run_distributed.cpp); `method = auto` does that from `distributed above`
  // elements on, where the mesh allows it, and takes METIS on rank 0 otherwise.
  using Method = inputs::DecompositionSpec::Method;
  const auto& decomposition = region_.decomposition;
  method_ = decomposition.method == Method::automatic ? Method::ptscotch : decomposition.method;
  if (decomposition.method == Method::automatic) {
    if (build_parts_distributed(decomposition.distributed_above)) return;
    method_ = Method::metis;
  } else if (decomposition.distributed_setup && build_parts_distributed()) {
    return;
  }
  std::optional<mesh::Mesh> whole;
  std::vector<int> part;
  parallel::NodeHolders holders;
  ContactFaces contact;
  std::optional<ContactTravel> travel;
  parallel::AxisScale scale = parallel::kUnitScale;
  std::exception_ptr error;
  if (root_) {
    // Arrays of 1 MB and more mapped and unmapped one by one, so that each one freed goes back to the
    // system at once: glibc's default threshold grows with the first large free (up to 32 MB), after
    // which the serial stage's temporaries stayed resident and added up
    // (docs/measurements/2026-11-26-bench-rank-counts.md "Rank 0's set-up, contact patches, positions-only
    // ghost rows"). It holds for the rest of the run: the loop allocates nothing, and the
    // outputs' occasional large buffers cost a map and unmap each.
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    try {
      whole.emplace(build_mesh(deck_));
      if (region_.contact) contact = contact_faces(*whole, *region_.contact);
      travel = contact_travel(deck_, *whole);
      scale = decomposition_scale(region_.decomposition, travel, ranks_);
    } catch (...) {
      error = std::current_exception();
    }
  }
  // The volume's partition is timed (the log's partition line): rank 0's wall time from the first
  // slab sent to the last part gathered with ptscotch, of the METIS or bisection call otherwise.
  const auto method = method_;
  const auto start = std::chrono::steady_clock::now();
  if (method == inputs::DecompositionSpec::Method::ptscotch) {
    // Collective: every rank must know rank 0's mesh is there before the slabs are sent.
    agree_on_errors(error);
    try {
      part = parallel::partition_elements_ptscotch(whole ? &*whole : nullptr, ranks_);
    } catch (const std::runtime_error& e) {  // thrown on every rank alike: rank 0 says it, once
      error = std::make_exception_ptr(SetupError(std::string("cannot partition the mesh for ") + std::to_string(ranks_) +
                                                 " ranks: " + e.what() + "; run with fewer ranks (mpirun -np N)"));
    }
    agree_on_errors(error);
  }
  if (root_ && !error) {
    double seconds = 0.0;
    try {
      try {
        if (method == inputs::DecompositionSpec::Method::rcb) part = parallel::partition_elements_rcb(*whole, ranks_, scale);
        if (method == inputs::DecompositionSpec::Method::metis) part = parallel::partition_elements(*whole, ranks_);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (region_.contact) {
          // The patches go to the surfaces the run enforces as slaves (build_contact may swap a pair).
          const inputs::ContactSpec enforced = as_enforced(*region_.contact, contact, block_wave_moduli(deck_, *whole));
          place_contact_patches(*whole, &enforced, ranks_, part, scale);
        }
      } catch (const std::runtime_error& e) {
        throw SetupError(std::string("cannot partition the mesh for ") + std::to_string(ranks_) + " ranks: " + e.what() +
                         "; run with fewer ranks (mpirun -np N)");
      }
      holders = parallel::node_holders(*whole, part);
      mesh_hash_ = mesh_sha256(*whole);
      report_partition(*whole, part, holders, scale, travel, seconds);
    } catch (...) {
      error = std::current_exception();
    }
  }
  agree_on_errors(error);
  parallel::broadcast(mesh_hash_, 0);
  parallel::MeshPart mine = parallel::distribute_mesh(whole ? &*whole : nullptr, &part, &holders);
  holders = {};
  part = {};
  if (region_.contact) broadcast_contact_faces(contact);
  // The results writers need only the whole mesh's outline (counts, blocks, length unit: broadcast
  // from rank 0 now, collective); each rank writes its own mesh rows (results.h5) or file (results.exo.N.r).
  if (region_.results) results_outline_ = output::outline_of(whole ? *whole : mesh::Mesh{}, region_.results->length_unit, true);
  whole.reset();
  for (const auto& [name, size] : mine.node_set_size) set_size_[name] = double(size);
  model_.emplace(build_model(deck_, std::move(mine), contact));
}

void DeckRun::report_partition(const mesh::Mesh& whole, const std::vector<int>& part,
                               const parallel::NodeHolders& holders, const parallel::AxisScale& scale,
                               const std::optional<ContactTravel>& travel, double seconds) {
  int shared = 0;
  for (int n = 0; n < whole.node_count(); ++n) shared += holders.count(n) > 1;
  std::vector<int> rank_elements(static_cast<std::size_t>(ranks_), 0);
  for (int p : part) ++rank_elements[p];
  const auto [fewest, most] = std::minmax_element(rank_elements.begin(), rank_elements.end());
  const auto& decomposition = region_.decomposition;
  const bool scaled = scale[0] != 1.0 || scale[1] != 1.0 || scale[2] != 1.0;
  // A scale the run chose says why: the prescribed motion that carries the contact zone.
  const bool chosen = !decomposition.coordinate_scale && travel && crosses_patches(*travel, ranks_);
  const std::string why = chosen ? format(": contact travels %.3g m along %c, node set %s", travel->distance,
                                          "xyz"[travel->axis], travel->node_set.c_str())
                                 : std::string();
  const std::string sides = scaled ? format(" (sides scaled %g %g %g%s)", scale[0], scale[1], scale[2], why.c_str())
                                   : std::string();
  std::string method;
  if (method_ == inputs::DecompositionSpec::Method::rcb) {
    method = "recursive coordinate bisection of the element centroids" + sides;
  } else if (method_ == inputs::DecompositionSpec::Method::ptscotch) {
    method = "PT-Scotch k-way partition of the element graph by all the ranks (the mesh read on rank 0)";
  } else {
    const int cluster = parallel::partition_cluster_size(whole.element_count(), ranks_);
    method = "METIS k-way partition of the " +
             (cluster > 1 ? format("graph of k-d clusters of up to %d elements", cluster) : std::string("element graph"));
  }
  // The patches' bisection takes the scale with either method; with rcb the line says it once.
  std::string patches;
  if (region_.contact)
    patches = ", contact surfaces in one compact patch per rank" +
              (method_ != inputs::DecompositionSpec::Method::rcb ? sides : std::string());
  log_.say(format("parallel: %d ranks, %s%s; %d-%d elements per rank; %d nodes on partition boundaries; partitioned "
                  "in %.3g s; every rank builds only its part",
                  ranks_, method.c_str(), patches.c_str(), *fewest, *most, shared, seconds));
}

void DeckRun::report_mesh(const Model& model) {
  const auto& d = model.domain;
  elements_ = d.global_element_count;
  std::vector<double> block_elements;
  for (const auto& b : model.blocks) block_elements.push_back(b.count);
  parallel::sum(block_elements.data(), static_cast<int>(block_elements.size()));
  log_.say(format("mesh: %d nodes, %d hex8 elements in %zu block(s); total mass %.6g kg", d.global_node_count, elements_,
                  model.blocks.size(), model.total_mass));
  for (std::size_t b = 0; b < model.blocks.size(); ++b)
    log_.say(format("  block %-16s %8.0f elements  %s  %s", model.blocks[b].name.c_str(), block_elements[b],
                    std::string(materials::model_name(model.blocks[b].material)).c_str(),
                    model.blocks[b].formulation == inputs::ElementFormulation::mean_quadrature ? "mean_quadrature"
                                                                                               : "fully_integrated"));
  double worst = 1.0, sum = 0.0;
  int worst_element = 0;
  for (int e = 0; e < model.mesh.element_count(); ++e) {
    const double q = mesh::scaled_jacobian(model.mesh, e);
    sum += q;
    if (q < worst) {
      worst = q;
      worst_element = d.global_element[e];
    }
  }
  parallel::sum(&sum, 1);
  worst = parallel::min_location(worst, worst_element);
  log_.say(format("element quality: scaled Jacobian min %.3f (element %d), mean %.3f", worst, worst_element + 1,
                  elements_ ? sum / elements_ : 0.0));
}

void DeckRun::start_from_restart() {
  stop_before_outputs("after the model was built");
  // A restart file is read and checked against the model before any output file is touched.
  integrator_.emplace(*model_, tc_);
  SetupFindings findings = model_->setup;
  for (const auto& b : model_->blocks) findings.block_names.push_back(b.name);
  guards_.emplace(region_.guards, std::move(findings), static_cast<long>(std::ceil(est_steps_)),
                  [this](const RunWarning& w) { announce(w); });
  block_translation_.emplace(*model_);
  strain_guard_.emplace(model_->blocks, model_->domain.global_element);
  if (options_.restart_path.empty()) return;
  std::exception_ptr error;
  try {
    // Any rank count: a file of another one is moved onto this run's partition by global numbers.
    const RestartLayout layout = integrator_->restart_layout();
    const int rank = parallel::rank(), ranks = parallel::size();
    // Test hook: the same rank count through the move as well (tests/parallel "*_remapped": bitwise).
    const char* hook = std::getenv("TRIBEX_RESTART_REMAP");
    const bool always_remap = hook && std::string(hook) == "1";
    resume_ = read_isolated(options_.restart_path,
                            [&] { return read_restart_for(options_.restart_path, layout, rank, ranks, always_remap); });
    const std::string changed = restart_difference(*resume_, deck_.resolved_text, mesh_hash_);
    if (!changed.empty() && !options_.restart_allow_changed)
      throw SetupError(options_.restart_path + ": error: this restart file was written by another run: " + changed +
                       "; resume with the deck and mesh that wrote it, or add --restart-allow-changed to go on with "
                       "these (for example a longer termination time)");
    if (!changed.empty()) log_.say("restart: --restart-allow-changed: " + changed);
    check_restart_values(*resume_, tc_, region_.results.has_value(), options_.restart_path);
    integrator_->restore_state(*resume_);
    guards_->restore(*resume_);
  } catch (const SetupError& e) {  // the archive's own words name the dataset; this names the file
    const std::string what = e.what();
    error = what.find(": error: ") != std::string::npos
                ? std::current_exception()
                : std::make_exception_ptr(SetupError(options_.restart_path + ": error: " + what));
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  log_.say(format("restart: resuming from %s at step %ld, t = %.6g s", options_.restart_path.c_str(),
                  integrator_->step_index(), integrator_->time()));
  if (resume_->has("remapped_from_ranks"))
    log_.say(format("restart: written by %lld rank(s), moved onto %d by global node and element numbers (applied "
                    "loads formed again; solver/README.md \"Restart\")",
                    resume_->integer("remapped_from_ranks"), ranks_));
}

// The files the deck reads besides itself and its includes: the mesh file, the AFM height map, the
// contact laws' data files (a fresh run never removes or replaces them, README.md "The output folder").
std::vector<std::string> DeckRun::deck_input_files() const {
  std::vector<std::string> files = deck_.files_read;
  files.push_back(deck_.path);
  for (const auto& m : deck_.models) {
    files.push_back(m.database_path);
    if (m.afm_surface) files.push_back(m.afm_surface->file);
  }
  if (region_.contact)
    for (const auto& i : region_.contact->interactions)
      for (const auto& [key, path] : i.values.paths) files.push_back(path);
  return files;
}

void DeckRun::claim_output_folder() {
  out_ = options_.output_directory;
  std::exception_ptr error;
  if (root_) {
    try {
      FolderRequest r;
      r.folder = out_;
      r.names = planned_output_names(region_.results && region_.results->xdmf, region_.results && region_.results->exodus,
                                     region_.restart ? region_.restart->ring_size : 0, ranks_);
      r.inputs = deck_input_files();
      const RunIdentity& id = summary_.identity;
      r.identity = OutputManifest{id.run_id, id.deck_path, id.deck_sha256, mesh_hash_, id.started_utc, id.host, {}, {}};
      r.resume = resume_.has_value();
      r.restart_path = options_.restart_path;
      r.restart_run_id = restart_run_id_;
      folder_.emplace(solver::claim_output_folder(r));
    } catch (...) {
      error = std::current_exception();
    }
  }
  agree_on_errors(error);
}

void DeckRun::report_output_folder() {
  const FolderClaim& f = *folder_;
  if (!f.lock->stale_holder().empty())
    log_.say("output folder " + out_.string() + ": took over the lock of a run that ended without releasing it (" +
             f.lock->stale_holder() + ")");
  if (!f.removed.empty())
    log_.say(format("output folder %s: removed %zu file(s) of an earlier run (those its manifest lists, unchanged)",
                    out_.string().c_str(), f.removed.size()));
  for (const auto& name : f.kept_inputs)
    log_.say("output folder " + out_.string() + ": kept the earlier run's " + name + ": the deck reads it");
}

void DeckRun::open_outputs() {
  namespace fs = std::filesystem;
  std::exception_ptr output_error;  // files are made by rank 0; agreed on below
  if (root_) {
    try {
      log_.open((out_ / "log.txt").string(), resume_.has_value());
      report_output_folder();
      log_.record("# resolved deck (defaults filled in, SI units)\n" + deck_.resolved_text + "\n");
    } catch (...) {
      output_error = std::current_exception();
    }
  }
  choose_history_columns();
  if (root_ && !output_error) {
    try {
      history_.emplace((out_ / "history.csv").string(), history_columns_, resume_ ? integrator_->step_index() : -1);
    } catch (...) {
      output_error = std::current_exception();
    }
  }
  // Node-set columns: sums over the set's nodes this rank owns, then over the ranks.
  const auto* hist_spec = region_.history ? &*region_.history : nullptr;
  const auto owned_nodes_of = [&](const std::string& name) {
    std::vector<int> nodes;
    for (int l : model_->mesh.node_sets.at(name))
      if (model_->domain.owned[l] > 0.0) nodes.push_back(l);
    return nodes;
  };
  if (hist_spec) {
    for (const auto& s : hist_spec->reaction_force_node_sets) reaction_sets_.push_back(owned_nodes_of(s));
    for (const auto& s : hist_spec->displacement_node_sets) {
      displacement_sets_.push_back(owned_nodes_of(s));
      displacement_set_size_.push_back(set_size_.at(s));
    }
  }
  set_sums_.assign(3 * (reaction_sets_.size() + displacement_sets_.size()), 0.0);
  history_schedule_.emplace(hist_spec ? hist_spec->time_increment : std::nullopt,
                            hist_spec ? hist_spec->step_increment : std::optional<int>(1), tc_.start_time);
  agree_on_errors(output_error);
  open_results();

  // Time spent by the earlier segments of a run resumed from restart files (NaN: not recorded,
  // a restart file of an earlier tribex), so that summary.json can report the whole run's cost.
  first_step_ = resume_ ? integrator_->step_index() : 0;
  if (resume_) {
    history_schedule_->set_next(resume_->scalar("history_next"));
    if (field_schedule_) field_schedule_->set_next(resume_->scalar("results_next"));
    earlier_wall_seconds_ = resume_->has("run_wall_seconds") ? resume_->scalar("run_wall_seconds") : NAN;
    earlier_loop_seconds_ = resume_->has("run_loop_seconds") ? resume_->scalar("run_loop_seconds") : NAN;
  }
  if (region_.restart) restart_output_.emplace(*region_.restart, out_.string(), summary_.identity.run_id);
  if (region_.restart) note_mpirun_signal_grace();
  // summary.json's space is taken before the loop (solver/output/summary_writer.hpp); agreed, as it can fail.
  std::exception_ptr reserve_error;
  if (root_) {
    try {
      reserve_summary_json((out_ / "summary.json").string(), summary_json_reserve_bytes(ranks_));
    } catch (...) {
      reserve_error = std::current_exception();
    }
  }
  agree_on_errors(reserve_error);
  if (root_) {
    try {
      // This process's segment (tribex join stitches per-rank results of several rank counts by them).
      folder_->manifest.segments.push_back({ranks_, integrator_->time()});
      record_written_files(out_, folder_->manifest);
    } catch (const SetupError& e) {
      log_.say(std::string("warning: ") + e.what());  // a later fresh run then keeps those files (safe)
    }
  }
}

// Under mpirun a SIGTERM or SIGINT leaves the ranks 2 x odls_base_sigkill_timeout to stop
// (solver/run/mpirun_grace.hpp); a model too large to stop in time is told so before its loop starts,
// from the measured seconds per element (the close repeats it with the run's own measurement).
void DeckRun::note_mpirun_signal_grace() {
  const double estimate = stop_seconds_per_element * elements_;
  const std::string note = mpirun_stop_grace_note(
      estimate, format("estimated from its %d elements at %g s each", elements_, stop_seconds_per_element));
  if (!note.empty()) log_.say(note);
}

void DeckRun::choose_history_columns() {
  // The material dissipation column only where a block's material dissipates (J2 plasticity), so
  // that the history of every other run keeps its columns.
  material_dissipation_ = std::any_of(model_->blocks.begin(), model_->blocks.end(),
                                      [](const ElementBlock& b) { return materials::dissipates(b.material); });
  history_columns_ = describe_history_columns(
      material_dissipation_, region_.history ? region_.history->reaction_force_node_sets : std::vector<std::string>{},
      region_.history ? region_.history->displacement_node_sets : std::vector<std::string>{},
      model_->mass_scaling.active);
  const auto rigid = describe_rigid_body_columns(model_->rigid_bodies);  // after the node-set columns
  history_columns_.insert(history_columns_.end(), rigid.begin(), rigid.end());
  rigid_values_.assign(rigid.size(), 0.0);
}

ResultsMeshRows DeckRun::results_mesh_rows() const {
  // This rank's rows of results.h5's /mesh in the slab's order: its owned nodes (ascending local, so
  // ascending global) and its elements, the connectivity in global node indices.
  const auto& domain = model_->domain;
  const auto& local = model_->mesh;
  ResultsMeshRows rows;
  rows.coordinates.reserve(3 * domain.owned_local_nodes().size());
  for (int l : domain.owned_local_nodes())
    for (int i = 0; i < 3; ++i) rows.coordinates.push_back(local.coordinates[3 * static_cast<std::size_t>(l) + static_cast<std::size_t>(i)]);
  rows.connectivity.reserve(local.connectivity.size());
  for (int l : local.connectivity) rows.connectivity.push_back(domain.global_node[static_cast<std::size_t>(l)]);
  return rows;
}

void DeckRun::open_results() {
  // results.h5: in a parallel run every rank writes the rows of its owned nodes and its elements
  // (runs of consecutive global rows) collectively with parallel HDF5, the mesh included: no rank needs
  // the whole mesh. results.exo: each rank its own file results.exo.N.r (its elements and the nodes they
  // use, joined by `tribex join`); one rank writes results.exo itself.
  if (!region_.results) return;
  const auto& domain = model_->domain;
  if (model_->contact) {
    surface_index_.assign(model_->mass.size(), -1);
    const auto& local = domain.surface_local();
    for (std::size_t k = 0; k < local.size(); ++k)
      if (local[k] >= 0) surface_index_[static_cast<std::size_t>(local[k])] = static_cast<int>(k);
  }
  const auto add_row = [](std::vector<std::array<unsigned long long, 2>>& runs, unsigned long long row) {
    if (!runs.empty() && runs.back()[0] + runs.back()[1] == row)
      ++runs.back()[1];
    else
      runs.push_back({row, 1});
  };
  for (int l : domain.owned_local_nodes()) add_row(slab_.node_runs, static_cast<unsigned long long>(domain.global_node[l]));
  for (int e : domain.global_element) add_row(slab_.element_runs, static_cast<unsigned long long>(e));
  slab_.node_rows = static_cast<long long>(domain.owned_local_nodes().size());
  slab_.element_rows = static_cast<long long>(domain.global_element.size());
  std::exception_ptr error;
  try {
    // A restarted run continues the folder's results.h5 (the steps up to the restart time stay) and
    // rewrites its results.exo (in parallel each rank its results.exo.N.r) with the steps before the restart time.
    const mesh::Mesh& mesh = model_->mesh;
    const auto resume_time = resume_ ? std::optional<double>(integrator_->time()) : std::nullopt;
    const ResultsOptions options{region_.results->length_unit, 1, summary_.identity.run_id, mesh_hash_};
    if (region_.results->xdmf && ranks_ > 1)
      results_ = std::make_unique<ResultsWriter>(out_.string(), *results_outline_, slab_, results_mesh_rows(), resume_time,
                                                 options);
    else if (region_.results->xdmf)
      results_ = std::make_unique<ResultsWriter>(out_.string(), mesh, nullptr, resume_time, options);
    if (region_.results->exodus) {
      std::vector<std::string> globals;  // the history columns, `step` first
      for (const auto& c : history_columns_) globals.push_back(c.name);
      if (ranks_ > 1)
        exodus_ = std::make_unique<ExodusWriter>(out_.string(), mesh, model_->domain, *results_outline_, std::move(globals),
                                                 resume_time);
      else
        exodus_ = std::make_unique<ExodusWriter>(out_.string(), mesh, std::move(globals), resume_time,
                                                 region_.results->length_unit);
    }
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  field_schedule_.emplace(region_.results->time_increment, region_.results->step_increment, tc_.start_time);
}

}  // namespace tribex::solver
