// SPDX-License-Identifier: MIT
#include "solver/output/output_tables.hpp"

#include "solver/output/json.hpp"

namespace tribex::solver {
namespace {

std::string number(double x) { return json_number(x, 17); }  // 17 digits: the figures round-trip

}  // namespace

// Restart order: the rows with a setter, in this order, are the restart array "energies".
std::span<const Field<Energies>> energy_fields() {
  using E = Energies;
  static const Field<E> table[] = {
      field<&E::kinetic>("kinetic", "J", "(1/2) sum m |v^n|^2 (docs/theory.md 1.3)"),
      field<&E::internal>("internal", "J", "stored elastic strain energy, sum V0 W"),
      field<&E::hourglass>("hourglass", "J", "stored energy of the hourglass stiffness (mean quadrature)"),
      field<&E::external_work>("external_work", "J", "work of the reactions at constrained dofs and of the applied loads"),
      field<&E::silent_boundary_dissipation>("silent_boundary_dissipation", "J",
                                             "energy absorbed by the silent-boundary dashpots"),
      field<&E::damping_dissipation>("damping_dissipation", "J", "energy dissipated by mass-proportional damping"),
      field<&E::viscous_dissipation>("viscous_dissipation", "J", "energy dissipated by bulk and hourglass viscosity"),
      field<&E::contact_work>("contact_work", "J",
                              "work absorbed by the contact (minus the work of contact forces on the bodies)"),
      field<&E::initial>("initial", "J", "kinetic + internal energy at the start, t = 0"),
      field<&E::plastic_dissipation>("plastic_dissipation", "J",
                                     "work dissipated by the material updates (J2 plasticity), sum V0 sigma:deps_p"),
  };
  return table;
}

// Restart order: the array "contact_totals". The definitions are the ones history.csv's columns
// show (history_columns.csv, `tribex run --list-columns`).
std::span<const Field<contact::ContactTotals>> contact_total_fields() {
  using C = contact::ContactTotals;
  static const Field<C> table[] = {
      field<&C::normal_force>("normal_force", "N", "net normal force on the slave nodes, compressive - adhesive"),
      field<&C::tangential_force>("tangential_force", "N", "magnitude of the vector sum of junction shear forces"),
      field<&C::compressive_force>("compressive_force", "N", "sum of the repulsive (penalty) normal forces on the slave nodes"),
      field<&C::adhesive_force>("adhesive_force", "N", "sum of the attractive (adhesion) normal forces on the slave nodes"),
      field<&C::adhesion_energy>("adhesion_energy", "J", "adhesive potential sum A_I U(g_I) (<= 0)"),
      field<&C::junction_capacity>("junction_capacity", "N", "junction strength tau* times the contact area"),
      field<&C::friction_power>("friction_power", "W", "rate of energy dissipated by the junction shear"),
      field<&C::area>("area", "m^2", "tributary areas of the slave nodes in contact (junction: in-contact face parts)"),
      field<&C::nodes>("nodes", "count", "slave nodes in contact"),
      field<&C::max_penetration>("max_penetration", "m", "deepest penetration of a slave node"),
      field<&C::radius_max>("radius_max", "m", "distance from the contact axis of the farthest slave node in contact"),
      field<&C::radius_edge>("radius_edge", "m",
                             "edge estimator: mean distance from the contact axis of the points where the gap changes "
                             "sign along slave-face edges (linear between the edge's nodes); 0 without a contact axis"),
      field<&C::searches>("searches", "count", "broad-phase searches this step"),
      field<&C::radius_pressure_fit>("radius_pressure_fit", "m",
                                     "pressure-fit estimator: zero of the least-squares line p^2 = alpha - beta r^2 through "
                                     "the contacting nodes' pressures at axis distance r; presumes an elliptic (Hertz-like) "
                                     "pressure; 0 without a contact axis or with under 3 nodes"),
      field<&C::real_area>("real_area", "m^2", "rough-surface law: real contact area sum A_I (A_c/A_0)"),
      field<&C::asperity_contacts>("asperity_contacts", "count", "rough-surface law: asperities in contact sum A_I (N/A_0)"),
      field<&C::nominal_area>("nominal_area", "m^2", "rough-surface law: nominal area within reach of the law"),
      field<&C::max_penetration_ratio>("max_penetration_ratio", "-",
                                       "deepest penetration over the local element size sqrt(A_I) (run guards)"),
      field<&C::penetration_node>("penetration_node", "-", "global node of max_penetration_ratio (0-based, -1: none)"),
      field<&C::motion_ratio>("motion_ratio", "-", "largest one-step surface motion over the capture distance (run guards)"),
      field<&C::motion_node>("motion_node", "-", "global node moving fastest in the pass of motion_ratio (0-based)"),
  };
  return table;
}

// Restart order: 13 values per warning (message is made again from them). summary.json writes the
// rows in this order, kind and message as strings and node 1-based (null: none).
std::span<const Field<RunWarning>> warning_fields() {
  using W = RunWarning;
  static const Field<W> table[] = {
      [] {
        auto f = field<&W::kind>("kind", "", "what was watched (solver/guards/README.md)");
        f.json = [](const W& w) { return json_string(kind_name(w.kind)); };
        return f;
      }(),
      field<&W::step>("step", "count", "step of the first crossing (set-up warnings: the first step)"),
      field<&W::time>("time", "s", "time of the first crossing"),
      field<&W::value>("value", "-", "the watched ratio at the first crossing"),
      field<&W::threshold>("threshold", "-", "the bound it crossed"),
      field<&W::max_value>("max_value", "-", "largest value of the watched ratio over the run"),
      field<&W::max_step>("max_step", "count", "step of max_value"),
      field<&W::max_time>("max_time", "s", "time of max_value"),
      [] {
        auto f = field<&W::node>("node", "", "node the value was measured at, 1-based (null: none)");
        f.json = [](const W& w) { return w.node >= 0 ? std::to_string(w.node + 1) : std::string("null"); };
        return f;
      }(),
      [] {
        auto f = field<&W::source>("source", "", "energy_error: the ledger term named as the likely source (null: none)");
        f.json = [](const W& w) {
          return w.source == EnergySource::none ? std::string("null") : json_string(source_name(w.source));
        };
        return f;
      }(),
      field<&W::source_change>("source_change", "J",
                               "energy_error: that term's change since since_step (contact_work: the energy the contact "
                               "gave the bodies)"),
      [] {
        auto f = field<&W::block>("block", "", "large_strain: the block's index in the deck's order (null: none)");
        f.json = [](const W& w) { return w.block >= 0 ? std::to_string(w.block) : std::string("null"); };
        return f;
      }(),
      field<&W::since_step>("since_step", "count", "energy_error: the step the error was last below half the warning"),
      {"message", "", "one line: what, where, and what to change", nullptr, nullptr,
       [](const W& w) { return json_string(w.message); }},
  };
  return table;
}

// summary.json "rank_counts", one object per rank in this order (solver/parallel/rank_counts.hpp).
// The per-step figures are the totals over the force evaluations that exchanged (one per step plus
// the initial one): the buffers are sized at set-up, so every step moves the same bytes.
std::span<const Field<parallel::RankCounts>> rank_count_fields() {
  using C = parallel::RankCounts;
  using F = Field<C>;
  static const F table[] = {
      field<&C::rank>("rank", "-", "MPI rank, 0-based"),
      field<&C::elements>("elements", "count", "elements of this rank"),
      field<&C::nodes>("nodes", "count", "nodes this rank holds (a shared node is counted by every rank that holds it)"),
      field<&C::owned_nodes>("owned_nodes", "count", "nodes this rank owns (a shared node: its lowest holder)"),
      field<&C::shared_nodes>("shared_nodes", "count", "held nodes that other ranks hold too (their forces are summed in the halo)"),
      field<&C::contact_faces>("contact_faces", "count",
                               "contact-surface faces of this rank's contact region (its own and ghost nodes; one rank: every face)"),
      field<&C::ghost_faces>("ghost_faces", "count",
                             "of contact_faces, those whose element is another rank's"),
      F{"halo_bytes_sent_per_step", "B", "shared-node forces sent to the neighbour ranks per force evaluation (MPI_Isend payload)",
        [](const C& c) { return c.halo_exchanges > 0 ? double(c.halo_bytes_sent) / double(c.halo_exchanges) : 0.0; }},
      F{"halo_bytes_received_per_step", "B", "shared-node forces received from the neighbour ranks per force evaluation",
        [](const C& c) { return c.halo_exchanges > 0 ? double(c.halo_bytes_received) / double(c.halo_exchanges) : 0.0; }},
      F{"contact_bytes_sent_per_step", "B",
        "contact ghost rows sent per force evaluation: owned surface nodes in other ranks' regions (x, v, f: 72 B each)",
        [](const C& c) { return c.surface_gathers > 0 ? double(c.contact_bytes_sent) / double(c.surface_gathers) : 0.0; }},
      F{"contact_bytes_received_per_step", "B", "contact ghost rows received per force evaluation: the ghost nodes of this rank's region (72 B each)",
        [](const C& c) {
          return c.surface_gathers > 0 ? double(c.contact_bytes_received) / double(c.surface_gathers) : 0.0;
        }},
      F{"contact_pairs_per_step", "count",
        "candidate (slave node, master face) pairs this rank's narrow phase evaluated per contact evaluation, all passes",
        [](const C& c) {
          return c.contact_evaluations > 0 ? double(c.contact_pairs) / double(c.contact_evaluations) : 0.0;
        }},
      field<&C::contact_evaluations>("contact_evaluations", "count", "contact force evaluations of this process"),
      field<&C::searches>("searches", "count", "full broad-phase searches of this process, all passes (the set-up search for initial overlaps included)"),
      field<&C::search_reuses>("search_reuses", "count",
                               "pass evaluations that kept the candidates of an earlier search (the cheap update)"),
      field<&C::peak_rss_setup_bytes>("peak_rss_setup_bytes", "B", "peak resident memory at the end of set-up (getrusage)"),
      field<&C::peak_rss_bytes>("peak_rss_bytes", "B", "peak resident memory of the run (getrusage, at the close)"),
      field<&C::exchange_peers>("exchange_peers", "count",
                                "ranks this rank exchanged values with in the set-up, contact region and output "
                                "exchanges (parallel/sparse_exchange.hpp), itself excluded; at most ranks - 1"),
  };
  return table;
}

// summary.json in file order. Text and objects have no unit (""); the "units" object lists the rest.
std::span<const Field<RunSummary>> summary_fields() {
  using R = RunSummary;
  using F = Field<R>;
  const auto text = [](std::string_view name, std::string_view definition, std::string (*json)(const R&)) {
    return F{name, "", definition, nullptr, nullptr, json};
  };
  static const F table[] = {
      text("status", "\"normal termination\", \"numerical failure: ...\", \"output failure: ...\" or \"interrupted\"",
           [](const R& s) { return json_string(s.status); }),
      field<&R::exit_code>("exit_code", "", "the process's exit code: 0, 3 (numerical or output failure), 130 (interrupted)"),
      text("tribex_version", "tribex version and `git describe` at build time",
           [](const R& s) { return json_string(s.identity.version); }),
      text("deck", "the deck file as given on the command line", [](const R& s) { return json_string(s.identity.deck_path); }),
      text("deck_sha256", "SHA-256 of the deck file's bytes (null: unreadable)", [](const R& s) {
        return s.identity.deck_sha256.empty() ? std::string("null") : json_string(s.identity.deck_sha256);
      }),
      text("started", "start time, ISO 8601 UTC", [](const R& s) { return json_string(s.identity.started_utc); }),
      text("host", "host name", [](const R& s) { return json_string(s.identity.host); }),
      text("run_id", "the run's identity (32 hex digits; kept by the runs resumed from its restart files), also in "
                     "log.txt, results.h5, the restart files and the output folder's .tribex_manifest.json",
           [](const R& s) { return json_string(s.identity.run_id); }),
      text("mesh_sha256", "SHA-256 of the mesh's coordinates and connectivity (restart files check it)",
           [](const R& s) { return json_string(s.identity.mesh_sha256); }),
      field<&R::steps>("steps", "count", "step index at the end"),
      field<&R::final_time>("final_time", "s", "simulated time at the end"),
      field<&R::nodes>("nodes", "count", "nodes of the mesh"),
      field<&R::elements>("elements", "count", "elements of the mesh"),
      field<&R::wall_seconds>("wall_time_s", "s", "wall-clock time of this process"),
      field<&R::loop_seconds>("loop_time_s", "s", "wall-clock time of this process's time-step loop"),
      field<&R::ns_per_element_step>("ns_per_element_step", "ns",
                                     "loop time / (elements x steps run by this process), in ns"),
      field<&R::first_step>("first_step", "count", "step this process started from (> 0: resumed from a restart file)"),
      field<&R::total_wall_seconds>("total_wall_time_s", "s",
                                    "wall-clock time of the whole run over its segments (null: an earlier one unknown)"),
      field<&R::total_loop_seconds>("total_loop_time_s", "s", "loop time of the whole run over its segments"),
      field<&R::contact_seconds>("contact_time_s", "s", "part of the loop spent in contact search and enforcement"),
      field<&R::contact_balance>("contact_balance", "-",
                                 "the busiest rank's candidate contact pairs over the even share, summed over the "
                                 "evaluations of this segment: 1 shared evenly, ranks: one rank has them all"),
      field<&R::ranks>("ranks", "count", "MPI ranks"),
      field<&R::communication_seconds>("communication_time_s", "s",
                                       "rank 0's loop time in halo exchange, surface gather and energy sums"),
      field<&R::initial_stable_time_step>("initial_stable_time_step", "s",
                                          "stable time step at t = 0, before the scale factor"),
      F{"controlling_element", "", "the element that sets initial_stable_time_step, 1-based",
        [](const R& s) { return double(s.controlling_element + 1); }, nullptr,
        [](const R& s) { return std::to_string(s.controlling_element + 1); }},
      field<&R::energy_error>("energy_error", "-", "|energy balance| / largest energy of the run at the end"),
      text("energy_unit", "the unit of the energies object", [](const R&) { return std::string("\"J\""); }),
      text("warnings", "the run guards' warnings list (solver/guards/README.md); units: units.warnings",
           [](const R& s) {
             std::string out = "[";
             for (std::size_t i = 0; i < s.warnings.size(); ++i) {
               out += i ? ",\n    {" : "\n    {";
               bool first = true;
               for (const Field<RunWarning>& f : warning_fields()) {
                 out += (first ? "\"" : ", \"") + std::string(f.name) + "\": ";
                 out += f.json ? f.json(s.warnings[i]) : number(f.get(s.warnings[i]));
                 first = false;
               }
               out += "}";
             }
             return out + (s.warnings.empty() ? "]" : "\n  ]");
           }),
      text("energies", "the energy ledger at the end (units: units.energies)", [](const R& s) {
        std::string out = "{";
        for (const Field<Energies>& f : energy_fields())
          out += (out.size() > 1 ? ", \"" : "\"") + std::string(f.name) + "\": " + number(f.get(s.energies));
        return out + "}";
      }),
      text("mass_scaling",
           "begin mass scaling (null without): target and unscaled time step (s), unscaled and added mass (kg), the "
           "added fraction (the contact surface nodes' included), the contact surface nodes raised, their mass factor "
           "(dt / dt_0)^2 and added mass (kg), and per block the scaled elements, mass, added mass and largest density "
           "factor",
           [](const R& s) {
             const MassScalingReport& m = s.mass_scaling;
             if (!m.active) return std::string("null");
             std::string out = "{\"target_time_step\": " + number(m.target_time_step) +
                               ", \"unscaled_time_step\": " + number(m.unscaled_time_step) +
                               ", \"unscaled_mass\": " + number(m.unscaled_mass) + ", \"added_mass\": " +
                               number(m.added_mass) + ", \"added_mass_fraction\": " + number(m.added_fraction()) +
                               ", \"maximum_added_mass_fraction\": " + number(m.maximum_added_mass_fraction) +
                               ", \"contact_nodes\": " + std::to_string(m.contact_nodes) +
                               ", \"contact_mass_factor\": " + number(m.contact_mass_factor) +
                               ", \"contact_added_mass\": " + number(m.contact_added_mass) + ", \"blocks\": [";
             for (std::size_t i = 0; i < m.blocks.size(); ++i) {
               const BlockMassScaling& b = m.blocks[i];
               out += std::string(i ? ",\n    " : "\n    ") + "{\"name\": " + json_string(b.name) +
                      ", \"scaled\": " + (b.listed ? "true" : "false") +
                      ", \"elements\": " + std::to_string(b.elements) +
                      ", \"scaled_elements\": " + std::to_string(b.scaled_elements) + ", \"mass\": " + number(b.mass) +
                      ", \"added_mass\": " + number(b.added_mass) + ", \"added_mass_fraction\": " +
                      number(b.fraction()) + ", \"largest_density_factor\": " + number(b.largest_scale) + "}";
             }
             return out + "\n  ]}";
           }),
      text("rank_counts",
           "per MPI rank, in rank order: elements, nodes, ghost faces, bytes exchanged and contact work per step, "
           "searches, peak memory (one entry in a serial run; units: units.rank_counts)",
           [](const R& s) {
             std::string out = "[";
             for (std::size_t i = 0; i < s.rank_counts.size(); ++i) {
               out += i ? ",\n    {" : "\n    {";
               bool first = true;
               for (const Field<parallel::RankCounts>& f : rank_count_fields()) {
                 out += (first ? "\"" : ", \"") + std::string(f.name) + "\": " + number(f.get(s.rank_counts[i]));
                 first = false;
               }
               out += "}";
             }
             return out + (s.rank_counts.empty() ? "]" : "\n  ]");
           }),
      text("parameters",
           "the deck's parameters {NAME = VALUE} in definition order, --set values applied, SI ({} without; "
           "units: units.parameters; inputs/README.md, \"Parameters\")",
           [](const R& s) {
             std::string out = "{";
             for (const inputs::DeckParameter& p : s.parameters)
               out += (out.size() > 1 ? ", " : "") + json_string(p.name) + ": " + number(p.value);
             return out + "}";
           }),
  };
  return table;
}

}  // namespace tribex::solver
