// SPDX-License-Identifier: MIT
#include "solver/run.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <memory>
#include <map>
#include <optional>
#include <span>

#include "inputs/sha256.hpp"
#include "solver/errors.hpp"
#include "solver/guards/block_translation.hpp"
#include "solver/guards/run_guards.hpp"
#include "solver/integrators/central_difference.hpp"
#include "solver/model.hpp"
#include "solver/output/history_writer.hpp"
#include "solver/output/results_writer.hpp"
#include "solver/output/run_log.hpp"
#include "solver/output/summary_writer.hpp"
#include "mesh/mesh_error.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/partition.hpp"
#include "solver/restart/restart_output.hpp"
#include "solver/restart/state_archive.hpp"
#include "solver/stop_signal.hpp"

namespace tribex::solver {
namespace {

/// "Every N steps or every dt seconds of simulated time", plus the first and the last state.
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

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string human_seconds(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 120) return format("%.0f s", s);
  if (s < 7200) return format("%.1f min", s / 60);
  return format("%.1f h", s / 3600);
}

// A fresh run into an existing output folder first removes the files tribex writes there (an earlier
// run's outputs and restart files, never anything else), so that runs are not mixed; a symbolic link in
// one of those names is removed as a link, its target untouched. A resumed run continues the folder.
std::size_t clear_owned_outputs(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return 0;
  std::vector<fs::path> owned;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const bool restart = name.rfind("restart", 0) == 0 && (name.ends_with(".h5") || name.ends_with(".h5.link"));
    const bool output = name == "history.csv" || name == "results.h5" || name == "results.xdmf" ||
                        name == "summary.json" || name == "summary.json.tmp" || name == "log.txt" ||
                        name == "results.xdmf.tmp";
    if (restart || output) owned.push_back(entry.path());
  }
  for (const auto& p : owned) {
    fs::remove(p, ec);  // a symlink itself, not its target
    if (ec) throw SetupError("cannot remove the earlier run's " + p.string() + " (" + ec.message() +
                             "); remove it or choose another output folder (-o)");
  }
  return owned.size();
}

// What a restart file records of the run that wrote it: the resolved deck (text, as integer codes) and the
// SHA-256 of the mesh (coordinates and connectivity). A resumed run compares them with its own.
std::vector<long long> as_codes(const std::string& text) {
  return std::vector<long long>(text.begin(), text.end());
}
std::string from_codes(const std::vector<long long>& codes) {
  std::string text;
  for (long long c : codes) text.push_back(static_cast<char>(c));
  return text;
}
std::string mesh_sha256(const mesh::Mesh& m) {
  std::string bytes(reinterpret_cast<const char*>(m.coordinates.data()), m.coordinates.size() * sizeof(double));
  bytes.append(reinterpret_cast<const char*>(m.connectivity.data()), m.connectivity.size() * sizeof(int));
  return inputs::sha256_hex(bytes);
}

// "" when the restart file was written by this deck and mesh; else what differs, one line.
std::string restart_difference(const StateArchive& archive, const std::string& deck_text, const std::string& mesh_hash) {
  if (!archive.has("deck_text") || !archive.has("mesh_sha256")) return "";  // an earlier tribex: not recorded
  if (from_codes(archive.integer_array("mesh_sha256")) != mesh_hash) return "the mesh differs (coordinates or connectivity)";
  const std::string old_text = from_codes(archive.integer_array("deck_text"));
  if (old_text == deck_text) return "";
  std::size_t line = 1, a = 0, b = 0;
  while (true) {
    const std::size_t ea = old_text.find('\n', a), eb = deck_text.find('\n', b);
    const std::string la = old_text.substr(a, ea == std::string::npos ? std::string::npos : ea - a);
    const std::string lb = deck_text.substr(b, eb == std::string::npos ? std::string::npos : eb - b);
    if (la != lb)
      return format("the resolved deck differs at its line %zu: '%s' then, '%s' now", line,
                    la.c_str(), lb.c_str());
    if (ea == std::string::npos || eb == std::string::npos) return "the resolved deck differs at its end";
    a = ea + 1;
    b = eb + 1;
    ++line;
  }
}

// Exit code of an error thrown inside run_deck (the CLI maps the same types the same way).
int exit_code_of(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const SetupError&) {
    return 2;
  } catch (const mesh::MeshError&) {
    return 2;
  } catch (const NumericalFailure&) {
    return 3;
  } catch (const StoppedByOtherRank& s) {
    return s.exit_code;
  } catch (...) {
    return 1;
  }
}

/// Collective: when any rank holds an error, the lowest such rank rethrows it (and prints it) and
/// every other rank throws StoppedByOtherRank with its exit code. For the steps of the set-up that
/// can fail on one rank only (files written by rank 0, a rank's group of a restart file).
void agree_on_errors(const std::exception_ptr& error) {
  if (parallel::size() == 1) {
    if (error) std::rethrow_exception(error);
    return;
  }
  const double first = parallel::min(error ? double(parallel::rank()) : 1e9);
  if (first >= 1e9) return;
  int code = error ? exit_code_of(error) : 0;
  parallel::broadcast(&code, 1, static_cast<int>(first));
  if (parallel::rank() == static_cast<int>(first)) std::rethrow_exception(error);
  throw StoppedByOtherRank(code);
}

}  // namespace

RunSummary run_deck(const inputs::Deck& deck, const RunOptions& options) {
  const auto wall_start = Clock::now();
  const bool root = parallel::is_root();
  const int ranks = parallel::size();
  RunLog log(options.quiet || !root);  // printed once, by rank 0
  const auto& region = deck.procedure.region;
  const auto& tc = deck.procedure.time_control;

  // Set-up is not interrupted half-way: a stop that arrives before the outputs exist ends the run here,
  // with nothing written (every rank at the same point).
  const auto stop_before_outputs = [&](const char* stage) {
    int stop = stop_signal();
    if (ranks > 1) stop = static_cast<int>(parallel::max(static_cast<long long>(stop)));
    if (stop && !options.check_only)
      throw Interrupted(std::string("interrupted during set-up (") + stage + "); nothing was written");
  };
  fault_signal_point("setup");
  const RunIdentity identity = identify_run(deck.path, ranks);
  log.say(identity_line(identity));
  // Bad input is found here, before any file is written. Every rank builds the whole model (the
  // same checks, the same errors), then keeps its part (parallel::localize).
  Model global = build_model(deck);
  const auto& mesh = global.mesh;
  const int elements = mesh.element_count();

  log.say(format("mesh: %d nodes, %d hex8 elements in %zu block(s); total mass %.6g kg", mesh.node_count(), elements,
                 global.blocks.size(), global.total_mass));
  for (const auto& b : global.blocks)
    log.say(format("  block %-16s %8d elements  %s  %s", b.name.c_str(), b.count,
                   std::string(materials::model_name(b.material)).c_str(),
                   b.formulation == inputs::ElementFormulation::mean_quadrature ? "mean_quadrature" : "fully_integrated"));
  {
    double worst = 1.0, sum = 0.0;
    int worst_element = 0;
    for (int e = 0; e < elements; ++e) {
      const double q = mesh::scaled_jacobian(mesh, e);
      sum += q;
      if (q < worst) {
        worst = q;
        worst_element = e;
      }
    }
    log.say(format("element quality: scaled Jacobian min %.3f (element %d), mean %.3f", worst, worst_element + 1,
                   elements ? sum / elements : 0.0));
  }
  const StableStep stable0 = compute_stable_time_step(global, nullptr);
  log.say(format("stable time step %.6g s (element %d controls it); scale factor %.3g => dt = %.6g s", stable0.dt,
                 stable0.controlling_element + 1, tc.time_step_scale_factor,
                 std::min(stable0.dt * tc.time_step_scale_factor, tc.maximum_time_step.value_or(INFINITY))));
  const double est_steps = (tc.termination_time - tc.start_time) /
                           std::min(stable0.dt * tc.time_step_scale_factor, tc.maximum_time_step.value_or(INFINITY));
  log.say(format("termination time %.6g s: about %.0f steps", tc.termination_time, std::ceil(est_steps)));
  log.say(format("constraints: %zu dofs; silent-boundary nodes: %zu; pressure loads: %zu", global.constraints.dof.size(),
                 global.silent.node.size(), global.pressures.size()));
  for (const auto& line : global.preflight) log.say(line);
  // Warnings go to stderr too when the terminal is otherwise quiet.
  const auto announce = [&log, root, quiet = options.quiet](const RunWarning& w) {
    log.say("warning: " + w.message);
    if (root && quiet) std::fprintf(stderr, "warning: %s\n", w.message.c_str());
  };
  for (const auto& w : global.setup.warnings) announce(w);

  RunSummary summary;
  summary.identity = identity;
  summary.elements = elements;
  summary.nodes = mesh.node_count();
  if (options.check_only) {
    summary.status = "checked";
    return summary;
  }

  // This rank's part. The whole mesh is kept until results.h5 has been created (rank 0 writes it
  // there, once); node-set sizes are those of the whole mesh.
  std::vector<int> part;
  try {
    part = parallel::partition_elements(mesh, ranks);
  } catch (const std::runtime_error& e) {
    throw SetupError(std::string("cannot partition the mesh for ") + std::to_string(ranks) + " ranks: " + e.what() +
                     "; run with fewer ranks (mpirun -np N)");
  }
  std::optional<mesh::Mesh> whole_mesh;
  if (ranks > 1 && region.results) whole_mesh = mesh;
  std::map<std::string, double> set_size;
  for (const auto& [name, nodes] : mesh.node_sets) set_size[name] = double(nodes.size());
  if (ranks > 1) {
    int shared = 0;
    std::vector<int> holder(static_cast<std::size_t>(mesh.node_count()), -1);
    for (int e = 0; e < elements; ++e)
      for (int I = 0; I < 8; ++I) {
        int& h = holder[mesh.connectivity[8 * e + I]];
        if (h >= 0 && h != part[e] && h < 1 << 20) {
          ++shared;
          h = 1 << 20;
        } else if (h < 0) {
          h = part[e];
        }
      }
    std::vector<int> rank_elements(static_cast<std::size_t>(ranks), 0);
    for (int e = 0; e < elements; ++e) ++rank_elements[part[e]];
    const auto [fewest, most] = std::minmax_element(rank_elements.begin(), rank_elements.end());
    log.say(format("parallel: %d ranks, METIS k-way partition of the element graph; %d-%d elements per rank; %d nodes "
                   "on partition boundaries",
                   ranks, *fewest, *most, shared));
  }
  stop_before_outputs("after the model was built");
  const std::string mesh_hash = mesh_sha256(global.mesh);
  Model model = parallel::localize(std::move(global), part);
  auto& domain = model.domain;

  // A restart file is read and checked against the model before any output file is touched.
  CentralDifference integrator(model, tc);
  RunGuards guards(region.guards, model.setup, static_cast<long>(std::ceil(est_steps)), announce);
  BlockTranslation block_translation(model);
  std::optional<StateArchive> resume;
  if (!options.restart_path.empty()) {
    std::exception_ptr error;
    try {
      resume = read_restart_file(options.restart_path);
      const std::string changed = restart_difference(*resume, deck.resolved_text, mesh_hash);
      if (!changed.empty() && !options.restart_allow_changed)
        throw SetupError(options.restart_path + ": error: this restart file was written by another run: " + changed +
                         "; resume with the deck and mesh that wrote it, or add --restart-allow-changed to go on with "
                         "these (for example a longer termination time)");
      if (!changed.empty()) log.say("restart: --restart-allow-changed: " + changed);
      integrator.restore_state(*resume);
      guards.restore(*resume);
    } catch (...) {
      error = std::current_exception();
    }
    agree_on_errors(error);
    log.say(format("restart: resuming from %s at step %ld, t = %.6g s", options.restart_path.c_str(),
                   integrator.step_index(), integrator.time()));
  }

  stop_before_outputs("before the output files were opened");
  // Outputs.
  namespace fs = std::filesystem;
  const fs::path out(options.output_directory);
  std::exception_ptr output_error;  // files are made by rank 0; agreed on below
  if (root) {
    try {
      std::error_code ec;
      const std::size_t cleared = resume ? 0 : clear_owned_outputs(out);
      fs::create_directories(options.output_directory, ec);
      if (ec) throw SetupError("cannot create output folder " + options.output_directory + ": " + ec.message());
      log.open((out / "log.txt").string(), resume.has_value());
      if (cleared) log.say(format("output folder %s: removed %zu file(s) of an earlier run (outputs, restart files)",
                                  out.string().c_str(), cleared));
      log.record("# resolved deck (defaults filled in, SI units)\n" + deck.resolved_text + "\n");
    } catch (...) {
      output_error = std::current_exception();
    }
  }

  std::vector<std::string> extra = {};
  const auto* hist_spec = region.history ? &*region.history : nullptr;
  // The material dissipation column only where a block's material dissipates (J2 plasticity), so
  // that the history of every other run keeps its columns.
  const bool material_dissipation = std::any_of(model.blocks.begin(), model.blocks.end(),
                                                [](const ElementBlock& b) { return materials::dissipates(b.material); });
  if (material_dissipation) extra.push_back("plastic_dissipation");
  if (hist_spec) {
    for (const auto& s : hist_spec->reaction_force_node_sets)
      for (const char* c : {"x", "y", "z"}) extra.push_back(s + "_reaction_" + c);
    for (const auto& s : hist_spec->displacement_node_sets)
      for (const char* c : {"x", "y", "z"}) extra.push_back(s + "_displacement_" + c);
  }
  std::optional<HistoryWriter> history;
  if (root && !output_error) {
    try {
      history.emplace((out / "history.csv").string(), extra, resume ? integrator.step_index() : -1);
    } catch (...) {
      output_error = std::current_exception();
    }
  }
  // Node-set columns: sums over the set's nodes this rank owns, then over the ranks.
  std::vector<std::vector<int>> reaction_sets, displacement_sets;
  std::vector<double> displacement_set_size;
  const auto owned_nodes_of = [&](const std::string& name) {
    std::vector<int> nodes;
    for (int l : model.mesh.node_sets.at(name))
      if (domain.owned[l] > 0.0) nodes.push_back(l);
    return nodes;
  };
  if (hist_spec) {
    for (const auto& s : hist_spec->reaction_force_node_sets) reaction_sets.push_back(owned_nodes_of(s));
    for (const auto& s : hist_spec->displacement_node_sets) {
      displacement_sets.push_back(owned_nodes_of(s));
      displacement_set_size.push_back(set_size.at(s));
    }
  }
  std::vector<double> set_sums(3 * (reaction_sets.size() + displacement_sets.size()), 0.0);
  Schedule history_schedule(hist_spec ? hist_spec->time_increment : std::nullopt,
                            hist_spec ? hist_spec->step_increment : std::optional<int>(1), tc.start_time);

  std::unique_ptr<ResultsWriter> results;
  std::optional<Schedule> field_schedule;
  agree_on_errors(output_error);
  // results.h5: in a parallel run every rank writes the rows of its owned nodes and its elements
  // (runs of consecutive global rows) collectively with parallel HDF5.
  ResultsSlab slab;
  if (region.results) {
    const auto add_row = [](std::vector<std::array<unsigned long long, 2>>& runs, unsigned long long row) {
      if (!runs.empty() && runs.back()[0] + runs.back()[1] == row)
        ++runs.back()[1];
      else
        runs.push_back({row, 1});
    };
    for (int l : domain.owned_local_nodes()) add_row(slab.node_runs, static_cast<unsigned long long>(domain.global_node[l]));
    for (int e : domain.global_element) add_row(slab.element_runs, static_cast<unsigned long long>(e));
    slab.node_rows = static_cast<long long>(domain.owned_local_nodes().size());
    slab.element_rows = static_cast<long long>(domain.global_element.size());
    std::exception_ptr error;
    try {
      // A restarted run continues the folder's results.h5 (the steps up to the restart time stay).
      results = std::make_unique<ResultsWriter>(out.string(), whole_mesh ? *whole_mesh : model.mesh,
                                                ranks > 1 ? &slab : nullptr,
                                                resume ? std::optional<double>(integrator.time()) : std::nullopt);
    } catch (...) {
      error = std::current_exception();
    }
    whole_mesh.reset();
    agree_on_errors(error);
    field_schedule.emplace(region.results->time_increment, region.results->step_increment, tc.start_time);
  }

  // Time spent by the earlier segments of a run resumed from restart files (NaN: not recorded,
  // a restart file of an earlier tribex), so that summary.json can report the whole run's cost.
  const long first_step = resume ? integrator.step_index() : 0;
  double earlier_wall_seconds = 0.0, earlier_loop_seconds = 0.0;
  if (resume) {
    history_schedule.set_next(resume->scalar("history_next"));
    if (field_schedule) field_schedule->set_next(resume->scalar("results_next"));
    earlier_wall_seconds = resume->has("run_wall_seconds") ? resume->scalar("run_wall_seconds") : NAN;
    earlier_loop_seconds = resume->has("run_loop_seconds") ? resume->scalar("run_loop_seconds") : NAN;
  }
  Clock::time_point loop_start;
  std::optional<RestartOutput> restart_output;
  if (region.restart) restart_output.emplace(*region.restart, out.string());
  const auto write_restart = [&]() {
    StateArchive archive;
    integrator.save_state(archive);
    guards.save(archive);
    archive.put_integers("deck_text", as_codes(deck.resolved_text));
    archive.put_integers("mesh_sha256", as_codes(mesh_hash));
    archive.put("history_next", history_schedule.next());
    archive.put("results_next", field_schedule ? field_schedule->next() : 0.0);
    archive.put("run_wall_seconds", earlier_wall_seconds + seconds_since(wall_start));
    archive.put("run_loop_seconds", earlier_loop_seconds + seconds_since(loop_start));
    const std::string file = restart_output->write(archive);
    log.record(format("restart file %s at step %ld, t = %.9g s\n", file.c_str(), integrator.step_index(), integrator.time()));
  };
  bool closing = false;
  const double end_time = tc.termination_time;
  const auto element_fields_due = [&](double t, long n) {
    return field_schedule && !region.results->element_variables.empty() &&
           field_schedule->due(t, n, t >= end_time * (1 - 1e-14));
  };
  integrator.set_stress_request(element_fields_due);

  std::vector<double> row;
  row.reserve(HistoryWriter::standard_columns().size() + extra.size());
  std::vector<double> element_stress(6 * static_cast<std::size_t>(model.mesh.element_count()), 0.0);
  std::vector<double> element_plastic_strain(static_cast<std::size_t>(model.mesh.element_count()), 0.0);
  std::vector<std::vector<double>> packed;  // parallel: this rank's rows of each field (output steps only)
  const bool terminal = root && !options.quiet && isatty(STDERR_FILENO);
  // Batch jobs and pipes get a heartbeat line instead of the terminal's carriage-return progress.
  const bool heartbeat = root && options.heartbeat_seconds > 0 && !isatty(STDOUT_FILENO);
  auto last_progress = Clock::now(), last_heartbeat = Clock::now();
  const double span = end_time - tc.start_time;
  const auto progress_text = [&](long n, double t, double error) {
    const double frac = span > 0 ? (t - tc.start_time) / span : 1.0;
    const double elapsed = seconds_since(loop_start);
    return format("step %ld | t %.4g s | %5.1f%% | ETA %s | dt %.3g s | energy error %.2e", n, t, 100.0 * frac,
                  human_seconds(frac > 0 ? elapsed * (1 - frac) / frac : NAN).c_str(), integrator.dt(), error);
  };

  auto write_outputs = [&]() {
    const double t = integrator.time();
    const long n = integrator.step_index();
    const auto& E = integrator.energies();
    if (history_schedule.due(t, n, closing)) {
      row.clear();
      const auto& C = integrator.contact_totals();
      row.insert(row.end(), {t, integrator.dt(), E.kinetic, E.internal, E.hourglass, E.external_work,
                             E.silent_boundary_dissipation, E.contact_work, E.relative_error(), C.normal_force,
                             C.tangential_force, C.area, double(C.nodes), E.damping_dissipation, E.viscous_dissipation,
                             std::sqrt(C.area / M_PI), C.radius_max, C.max_penetration, integrator.momentum()[0],
                             integrator.momentum()[1], integrator.momentum()[2], C.radius_edge, C.adhesive_force,
                             C.compressive_force, C.tangential_force, C.junction_capacity, C.adhesion_energy,
                             C.friction_power, C.radius_pressure_fit, C.real_area, C.asperity_contacts,
                             C.apparent_pressure()});
      if (material_dissipation) row.push_back(E.plastic_dissipation);
      std::fill(set_sums.begin(), set_sums.end(), 0.0);
      std::size_t c = 0;
      for (const auto& set : reaction_sets) {
        for (int node : set)
          for (int i = 0; i < 3; ++i) set_sums[c + i] += integrator.reaction()[3 * node + i];
        c += 3;
      }
      for (const auto& set : displacement_sets) {
        for (int node : set)
          for (int i = 0; i < 3; ++i) set_sums[c + i] += integrator.displacement()[3 * node + i];
        c += 3;
      }
      parallel::sum(set_sums.data(), static_cast<int>(set_sums.size()));
      for (std::size_t k = 0; k < displacement_sets.size(); ++k)
        for (int i = 0; i < 3; ++i) set_sums[3 * (reaction_sets.size() + k) + i] /= displacement_set_size[k];
      row.insert(row.end(), set_sums.begin(), set_sums.end());
      if (history) history->write_row(n, row);
      history_schedule.done(t);
    }
    if (field_schedule && field_schedule->due(t, n, closing)) {
      // Parallel runs write the rows this rank owns: nodal fields packed from local (or, for the
      // contact fields, global) numbering; the rank's elements are its rows already.
      std::vector<FieldView> nodal, element;
      std::size_t g = 0;
      const auto owned_rows = [&](const std::vector<double>& values, int components, bool global_numbering) {
        if (domain.serial()) return std::span<const double>(values);
        if (packed.size() <= g) packed.emplace_back();
        auto& buffer = packed[g++];
        buffer.clear();
        for (int l : domain.owned_local_nodes()) {
          const std::size_t r = static_cast<std::size_t>(global_numbering ? domain.global_node[l] : l);
          buffer.insert(buffer.end(), values.begin() + components * r, values.begin() + components * (r + 1));
        }
        return std::span<const double>(buffer);
      };
      for (const auto& name : region.results->nodal_variables) {
        const std::vector<double>* v = nullptr;
        if (name == "displacement") v = &integrator.displacement();
        if (name == "velocity") v = &integrator.velocity();
        if (name == "acceleration") v = &integrator.acceleration();
        if (name == "force") v = &integrator.force();
        if (v) nodal.push_back({name, 3, owned_rows(*v, 3, false)});
        if (model.contact && name == "contact_traction") nodal.push_back({name, 3, owned_rows(model.contact->traction(), 3, true)});
        if (model.contact && name == "contact_status") nodal.push_back({name, 1, owned_rows(model.contact->status(), 1, true)});
      }
      for (const auto& name : region.results->element_variables) {
        if (name == "stress") {
          for (const auto& b : model.blocks)
            std::copy(b.stress.begin(), b.stress.end(), element_stress.begin() + 6 * b.first_element);
          element.push_back({"stress", 6, element_stress});
        } else if (name == "equivalent_plastic_strain") {
          for (const auto& b : model.blocks) equivalent_plastic_strain(b, element_plastic_strain.data() + b.first_element);
          element.push_back({name, 1, element_plastic_strain});
        }
      }
      if (results) results->write_step(t, nodal, element);
      field_schedule->done(t);
    }
    guards.observe(n, t, E, model.contact ? &integrator.contact_totals() : nullptr,
                   guards.wants_sample(n) ? block_translation.kinetic_energy(integrator.velocity()) : 0.0);
    if (terminal && seconds_since(last_progress) > 0.5) {
      last_progress = Clock::now();
      std::fprintf(stderr, "\r  %s   ", progress_text(n, t, E.relative_error()).c_str());
      std::fflush(stderr);
    }
    if (heartbeat && seconds_since(last_heartbeat) >= options.heartbeat_seconds) {
      last_heartbeat = Clock::now();
      log.say("heartbeat: " + progress_text(n, t, E.relative_error()));
    }
  };

  fault_signal_point("outputs");
  const std::function<void()> on_time_n = write_outputs;  // built once: no allocation per step
  const double contact_seconds_before = integrator.contact_seconds();  // earlier segments' (restart file)
  log.say("running ...");
  loop_start = Clock::now();
  bool stopped_at_step = false;
  try {
    if (!resume) integrator.init();
    while (!integrator.finished()) {
      integrator.step(on_time_n);
      stopped_at_step = options.stop_at_step >= 0 && integrator.step_index() >= options.stop_at_step;
      bool stop = stop_signal() || stopped_at_step;
      if (ranks > 1) stop = parallel::max(static_cast<long long>(stop)) > 0;  // every rank stops at the same step
      if (restart_output && (stop || restart_output->due(integrator.step_index()))) write_restart();
      if (stop) break;
    }
    closing = true;
    integrator.close(on_time_n);
    const bool interrupted = stop_signal() || stopped_at_step;
    summary.exit_code = interrupted ? 130 : 0;
    summary.status = interrupted ? "interrupted" : "normal termination";
  } catch (const NumericalFailure& e) {
    summary.exit_code = 3;
    summary.status = std::string("numerical failure: ") + e.what();
  } catch (const OutputError& e) {
    summary.exit_code = 3;
    summary.status = std::string("output failure: ") + e.what();
  }
  summary.loop_seconds = seconds_since(loop_start);
  if (terminal) std::fprintf(stderr, "\n");
  guards.finish();
  summary.warnings = guards.warnings();
  try {
    if (results) results->flush();  // collective in a parallel run: every rank gets here
  } catch (const OutputError& e) {
    if (summary.exit_code == 0 || summary.exit_code == 130) {
      summary.exit_code = 3;
      summary.status = std::string("output failure: ") + e.what();
    }
  }

  summary.steps = integrator.step_index();
  summary.first_step = first_step;
  summary.total_wall_seconds = earlier_wall_seconds + seconds_since(wall_start);
  summary.total_loop_seconds = earlier_loop_seconds + summary.loop_seconds;
  summary.contact_seconds = integrator.contact_seconds();
  summary.ranks = ranks;
  summary.communication_seconds = model.domain.communication_seconds;
  summary.final_time = integrator.time();
  summary.energy_error = integrator.energies().relative_error();
  const long steps_run = summary.steps - summary.first_step;  // by this process
  summary.ns_per_element_step =
      steps_run > 0 && elements > 0 ? 1e9 * summary.loop_seconds / (double(elements) * double(steps_run)) : 0.0;
  summary.wall_seconds = seconds_since(wall_start);
  if (root) {
    try {
      write_summary_json((out / "summary.json").string(), summary, integrator.energies(), stable0);
    } catch (const std::exception& e) {  // a full disk: say so; the status still ends the log and stderr
      std::fprintf(stderr, "error: %s\n", e.what());
      if (summary.exit_code == 0) {
        summary.exit_code = 3;
        summary.status = std::string("output failure: ") + e.what();
      }
    }
  }
  log.say(format("%ld steps to t = %.6g s in %.3g s wall (loop %.3g s, %.1f ns per element per step); energy error %.3e",
                 steps_run, summary.final_time, summary.wall_seconds, summary.loop_seconds,
                 summary.ns_per_element_step, summary.energy_error));
  if (summary.first_step > 0 && std::isfinite(summary.total_wall_seconds))
    log.say(format("resumed at step %ld: the whole run, %ld steps, took %.4g s wall (loop %.4g s) over its segments",
                   summary.first_step, summary.steps, summary.total_wall_seconds, summary.total_loop_seconds));
  else if (summary.first_step > 0)
    log.say(format("resumed at step %ld: the whole run's time is unknown (an earlier segment's restart file did not "
                   "record it; add the segments' wall times in log.txt)", summary.first_step));
  log.say(format("outputs: %s/{history.csv,summary.json,log.txt%s}", out.string().c_str(),
                 results ? ",results.h5,results.xdmf" : ""));
  if (model.contact) {
    const double segment_contact_seconds = summary.contact_seconds - contact_seconds_before;
    log.say(format("contact: %.3g s of the loop (%.1f %%), %ld broad-phase searches", segment_contact_seconds,
                   summary.loop_seconds > 0 ? 100.0 * segment_contact_seconds / summary.loop_seconds : 0.0,
                   model.contact->total_searches()));
  }
  if (ranks > 1) {
    // Waiting at the exchange is most of it: the rank that waits least carries the most work.
    const double share = summary.loop_seconds > 0 ? 100.0 * summary.communication_seconds / summary.loop_seconds : 0.0;
    const double least = parallel::min(share), most = parallel::max(share);
    log.say(format("parallel: %d ranks; rank 0 spent %.3g s of the loop (%.1f %%) in communication, waits included "
                   "(%.1f-%.1f %% over the ranks)",
                   ranks, summary.communication_seconds, share, least, most));
  }
  std::string closing_line = summary.exit_code == 0 ? "Normal termination" : "Error termination: " + summary.status;
  if (!summary.warnings.empty()) {
    std::string kinds;
    for (const auto& w : summary.warnings) kinds += (kinds.empty() ? "" : ", ") + std::string(kind_name(w.kind));
    closing_line += format(" (%zu warning%s: %s; see summary.json)", summary.warnings.size(),
                           summary.warnings.size() == 1 ? "" : "s", kinds.c_str());
  }
  log.say(closing_line);
  // --quiet silences the terminal, not the reason a run failed: that still goes to stderr.
  if (summary.exit_code != 0 && root && options.quiet) std::fprintf(stderr, "%s\n", closing_line.c_str());
  return summary;
}

}  // namespace tribex::solver
