// SPDX-License-Identifier: MIT
// The data-struct tables (solver/output/output_tables.hpp) and what they drive: restart arrays that
// keep the layout of restart files written before the tables (format version 1, pinned here value
// by value), summary.json's keys in their order with a "units" object; history columns in their
// order, and the plain contact_radius the estimator its definition says.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "solver/output/history_columns.hpp"
#include "solver/output/output_tables.hpp"
#include "solver/output/summary_writer.hpp"

using namespace tribex;
using solver::Field;

namespace {

template <class T>
void expect_described(std::span<const Field<T>> table, const char* what) {
  std::set<std::string_view> names;
  for (const Field<T>& f : table) {
    EXPECT_TRUE(names.insert(f.name).second) << what << ": duplicate " << f.name;
    EXPECT_GT(f.definition.size(), 5u) << what << ": " << f.name;
    EXPECT_TRUE(f.get || f.json) << what << ": " << f.name << " has no value";
    EXPECT_TRUE(!f.set || f.get) << what << ": " << f.name << " is restored but not saved";
    EXPECT_EQ(f.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_"), std::string_view::npos) << f.name;
  }
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST(OutputTables, EveryFieldIsNamedOnceAndDefined) {
  expect_described(solver::energy_fields(), "energies");
  expect_described(solver::contact_total_fields(), "contact totals");
  expect_described(solver::warning_fields(), "warnings");
  expect_described(solver::summary_fields(), "summary.json");
  expect_described(solver::rank_count_fields(), "rank_counts");
  for (const auto& f : solver::energy_fields()) EXPECT_EQ(f.unit, "J") << f.name;
}

// Restart files of format version 1 hold these arrays in exactly this order; a table row moved or
// inserted would make old files restore the wrong fields, so the order is pinned value by value.
TEST(OutputTables, EnergyLedgerRestartArrayKeepsItsLayout) {
  solver::Energies e;
  e.kinetic = 1;
  e.internal = 2;
  e.hourglass = 3;
  e.external_work = 4;
  e.silent_boundary_dissipation = 5;
  e.damping_dissipation = 6;
  e.viscous_dissipation = 7;
  e.contact_work = 8;
  e.initial = 9;
  e.plastic_dissipation = 10;
  const auto a = solver::stored_array(solver::energy_fields(), e);
  EXPECT_EQ(a, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  solver::Energies back;
  solver::restore_array(solver::energy_fields(), a, back, "the energy ledger");
  EXPECT_EQ(solver::stored_array(solver::energy_fields(), back), a);
  EXPECT_EQ(back.plastic_dissipation, 10.0);
}

TEST(OutputTables, ContactTotalsRestartArrayKeepsItsLayoutAndIntegers) {
  contact::ContactTotals c;
  double x = 0.5;
  for (const auto& f : solver::contact_total_fields()) f.set(c, x++);  // 0.5, 1.5, ... (integers truncate)
  c.nodes = 1234567;
  c.penetration_node = -1;
  c.motion_node = 2000000001;
  const auto a = solver::stored_array(solver::contact_total_fields(), c);
  EXPECT_EQ(a, (std::vector<double>{c.normal_force, c.tangential_force, c.compressive_force, c.adhesive_force,
                                    c.adhesion_energy, c.junction_capacity, c.friction_power, c.area, 1234567,
                                    c.max_penetration, c.radius_max, c.radius_edge, double(c.searches),
                                    c.radius_pressure_fit, c.real_area, c.asperity_contacts, c.nominal_area,
                                    c.max_penetration_ratio, -1, c.motion_ratio, 2000000001}));
  contact::ContactTotals back;
  solver::restore_array(solver::contact_total_fields(), a, back, "the contact totals");
  EXPECT_EQ(back.nodes, 1234567);
  EXPECT_EQ(back.penetration_node, -1);
  EXPECT_EQ(back.motion_node, 2000000001);
  EXPECT_EQ(solver::stored_array(solver::contact_total_fields(), back), a);
}

TEST(OutputTables, WarningRestartRunIsThirteenValuesAndTheMessageIsNotKept) {
  solver::RunWarning w;
  w.kind = solver::WarningKind::contact_motion;
  w.step = 857;
  w.time = 6.6e-11;
  w.value = 1.0 / 3.0;
  w.threshold = 0.5;
  w.max_value = 1.08;
  w.max_step = 900;
  w.max_time = 7e-11;
  w.node = 515;
  w.source = solver::EnergySource::contact;
  w.source_change = -4.95e-19;
  w.block = 2;
  w.since_step = 800;
  w.message = "not kept";
  std::vector<double> flat;
  solver::append_stored(solver::warning_fields(), w, flat);
  EXPECT_EQ(flat.size(), 13u);
  EXPECT_EQ(std::vector<double>(flat.begin(), flat.begin() + 9),
            (std::vector<double>{3, 857, 6.6e-11, 1.0 / 3.0, 0.5, 1.08, 900, 7e-11, 515}));
  solver::RunWarning back;
  solver::restore_stored(solver::warning_fields(), flat.data(), back);
  EXPECT_EQ(back.kind, solver::WarningKind::contact_motion);
  EXPECT_EQ(back.step, 857);
  EXPECT_EQ(back.max_step, 900);
  EXPECT_EQ(back.node, 515);
  EXPECT_EQ(back.value, 1.0 / 3.0);
  EXPECT_EQ(back.source, solver::EnergySource::contact);
  EXPECT_EQ(back.source_change, -4.95e-19);
  EXPECT_EQ(back.block, 2);
  EXPECT_EQ(back.since_step, 800);
  EXPECT_TRUE(back.message.empty());
}

TEST(OutputTables, ArrayOfAnotherLengthIsRefusedWithBothCounts) {
  solver::Energies e;
  try {
    solver::restore_array(solver::energy_fields(), std::vector<double>(9, 0.0), e, "the energy ledger");
    FAIL() << "a 9-value energy ledger was accepted";
  } catch (const solver::SetupError& err) {
    EXPECT_NE(std::string(err.what()).find("the energy ledger has 9 values, this tribex keeps 10"), std::string::npos)
        << err.what();
  }
}

TEST(SummaryJson, KeysInTheirOrderThenUnits) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_summary_json_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  solver::RunSummary s;
  s.status = "numerical failure: element 8 \"inverted\"";
  s.exit_code = 3;
  s.identity.version = "0.1.0 (git test)";
  s.identity.deck_path = "deck.i";
  s.steps = 1234;
  s.final_time = 0.125;  // exact in binary: printed with 17 digits as is
  s.total_wall_seconds = NAN;  // an earlier segment unknown: null
  s.initial_stable_time_step = 0.0625;
  s.controlling_element = 7;
  s.energies.kinetic = 1.5;
  s.energies.plastic_dissipation = 0.25;
  solver::RunWarning w;
  w.kind = solver::WarningKind::penetration;
  w.step = 10;
  w.message = "deep";
  s.warnings = {w};
  solver::parallel::RankCounts c;  // rank_counts (issue 25): per-step figures are totals over the exchanges
  c.rank = 1;
  c.elements = 20;
  c.halo_exchanges = 4;
  c.halo_bytes_sent = 96;
  c.contact_evaluations = 4;
  c.contact_pairs = 10;
  c.peak_rss_bytes = 1 << 20;
  c.exchange_peers = 3;
  s.rank_counts = {c};
  s.parameters = {{"W", 0.06, "J/m^2", true, {}}, {"n", 3, "", false, {}}};  // deck parameters (--set W=0.06)
  solver::write_summary_json((dir / "summary.json").string(), s);
  const std::string text = read_file(dir / "summary.json");

  // The keys scripts read, in the order summary.json has always had them, then "units".
  std::vector<std::string> keys;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("  \"", 0) == 0) keys.push_back(line.substr(3, line.find('"', 3) - 3));
  EXPECT_EQ(keys, (std::vector<std::string>{"status", "exit_code", "tribex_version", "deck", "deck_sha256", "started",
                                            "host", "run_id", "mesh_sha256", "steps", "final_time", "nodes", "elements", "wall_time_s",
                                            "loop_time_s", "ns_per_element_step", "first_step", "total_wall_time_s",
                                            "total_loop_time_s", "contact_time_s", "contact_balance", "ranks",
                                            "communication_time_s", "initial_stable_time_step", "controlling_element",
                                            "energy_error", "energy_unit", "warnings", "energies", "mass_scaling",
                                            "rank_counts", "parameters", "units"}));
  for (const char* expected :
       {"\"status\": \"numerical failure: element 8 \\\"inverted\\\"\",\n", "\"exit_code\": 3,\n", "\"steps\": 1234,\n",
        "\"final_time\": 0.125,\n", "\"deck_sha256\": null,\n", "\"total_wall_time_s\": null,\n",
        "\"initial_stable_time_step\": 0.0625,\n", "\"controlling_element\": 8,\n", "\"energy_unit\": \"J\",\n",
        "{\"kind\": \"penetration\", \"step\": 10, \"time\": 0, ", "\"node\": null, \"source\": null, \"source_change\": 0, \"block\": null, \"since_step\": 0, \"message\": \"deep\"}",
        "\"energies\": {\"kinetic\": 1.5, \"internal\": 0, ", "\"plastic_dissipation\": 0.25},\n",
        "\"units\": {\"steps\": \"count\", \"final_time\": \"s\", ", "\"energy_error\": \"-\", \"energies\": {\"kinetic\": \"J\", ",
        "\"warnings\": {\"step\": \"count\", \"time\": \"s\", ", "\"mass_scaling\": null,\n",
        "\"rank_counts\": [\n    {\"rank\": 1, \"elements\": 20, \"nodes\": 0, ",
        "\"halo_bytes_sent_per_step\": 24, \"halo_bytes_received_per_step\": 0, ",
        "\"contact_pairs_per_step\": 2.5, \"contact_evaluations\": 4, ", "\"peak_rss_bytes\": 1048576, \"exchange_peers\": 3}\n  ],\n",
        "\"rank_counts\": {\"rank\": \"-\", \"elements\": \"count\", ", "\"peak_rss_bytes\": \"B\", \"exchange_peers\": \"count\"}, \"parameters\": {\"W\": \"J/m^2\", \"n\": \"-\"}}\n}\n",
        "\"parameters\": {\"W\": 0.059999999999999998, \"n\": 3},\n"})
    EXPECT_NE(text.find(expected), std::string::npos) << "summary.json lacks " << expected << "\n" << text;
  EXPECT_EQ(text.substr(text.size() - 5), "}}\n}\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "summary.json.tmp"));
}

namespace {

double column(std::string_view name, const solver::HistoryState& s) {
  for (const auto& c : solver::history_columns())
    if (c.name == name) return c.value(s);
  ADD_FAILURE() << "no history column " << name;
  return NAN;
}

}  // namespace

// Scripts read history.csv by name, some by position: the columns keep their order and new ones go
// at the end (plastic_dissipation, present only where a material dissipates, then added_mass, present only with mass scaling).
TEST(HistoryColumns, OrderIsKeptAndNewColumnsComeLast) {
  std::vector<std::string_view> names;
  for (const auto& c : solver::history_columns()) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string_view>{
                       "time", "dt", "kinetic_energy", "internal_energy", "hourglass_energy", "external_work",
                       "silent_boundary_dissipation", "contact_work", "energy_error", "contact_normal_force",
                       "contact_tangential_force", "contact_area", "contact_nodes", "damping_dissipation",
                       "viscous_dissipation", "contact_radius", "contact_radius_max", "contact_max_penetration",
                       "momentum_x", "momentum_y", "momentum_z", "contact_radius_edge", "adhesive_force",
                       "compressive_force", "friction_force", "tau_star_times_area", "adhesion_energy",
                       "friction_power", "contact_radius_pressure_fit", "real_contact_area", "asperity_contacts",
                       "apparent_pressure", "contact_radius_area", "plastic_dissipation", "added_mass"}));
}

// contact_radius is the edge estimate where there is one (a contact axis, a contact boundary on the
// slave surface), else the area one; every estimator keeps a column named after it.
TEST(HistoryColumns, PlainContactRadiusIsTheEdgeEstimateWhereItIsDefined) {
  solver::Energies e;
  contact::ContactTotals c;
  const double momentum[3] = {0.0, 0.0, 0.0};
  const solver::HistoryState s{0.0, 0.0, e, c, momentum};
  c.area = M_PI * 4e-18;  // a disc of radius 2 nm
  c.radius_edge = 1.9e-9;
  c.radius_pressure_fit = 1.85e-9;
  EXPECT_DOUBLE_EQ(column("contact_radius_area", s), 2e-9);
  EXPECT_EQ(column("contact_radius", s), 1.9e-9);
  EXPECT_EQ(column("contact_radius_edge", s), 1.9e-9);
  EXPECT_EQ(column("contact_radius_pressure_fit", s), 1.85e-9);
  c.radius_edge = 0.0;  // no contact axis in the deck (or no contact boundary on the slave surface)
  c.radius_pressure_fit = 0.0;
  EXPECT_DOUBLE_EQ(column("contact_radius", s), 2e-9);
  c.area = 0.0;  // no contact
  EXPECT_EQ(column("contact_radius", s), 0.0);
  // Each definition says which estimator it is.
  const std::map<std::string, std::string> starts = {
      {"contact_radius", "contact radius, best estimate: contact_radius_edge where it is defined"},
      {"contact_radius_edge", "edge estimator:"},
      {"contact_radius_pressure_fit", "pressure-fit estimator:"},
      {"contact_radius_area", "area estimator: sqrt(contact_area / pi)"}};
  int seen = 0;
  for (const auto& info : solver::describe_history_columns(false, {}, {})) {
    const auto it = starts.find(info.name);
    if (it == starts.end()) continue;
    EXPECT_EQ(info.definition.rfind(it->second, 0), 0u) << info.name << ": " << info.definition;
    ++seen;
  }
  EXPECT_EQ(seen, 4);
}
