// SPDX-License-Identifier: MIT
#include "solver/output/history_columns.hpp"

#include <cmath>

#include "solver/output/output_tables.hpp"

namespace tribex::solver {
namespace {

using S = HistoryState;

HistoryColumn derived(std::string_view name, std::string_view unit, std::string_view definition,
                      double (*value)(const S&)) {
  return {name, unit, definition, value};
}
// A column that shows field `field` of the energy ledger / the contact totals under the name `name`.
HistoryColumn energy(std::string_view name, std::string_view field, bool material_dissipation_only = false) {
  const Field<Energies>& f = field_named(energy_fields(), field);
  return {name, f.unit, f.definition, nullptr, &f, nullptr, material_dissipation_only};
}
HistoryColumn contact(std::string_view name, std::string_view field) {
  const Field<contact::ContactTotals>& f = field_named(contact_total_fields(), field);
  return {name, f.unit, f.definition, nullptr, nullptr, &f};
}

double area_radius(const contact::ContactTotals& c) { return std::sqrt(c.area / M_PI); }

// The plain contact_radius is the edge estimate wherever it is defined: on the Hertz decks it is
// within 2.7 % of Hertz where the area estimate reads 3-10 % high (verification/hertz/README.md, "The
// contact-radius estimators"). The pressure fit is closer still there (1.4 %) but presumes an
// elliptic pressure, so it stays a column of its own for the decks that have one. The edge estimate
// needs a contact axis and a contact zone with a boundary on the slave surface (else it is 0); the
// area estimate is what there is without them.
double best_radius(const contact::ContactTotals& c) { return c.radius_edge > 0.0 ? c.radius_edge : area_radius(c); }

// Present only in runs with `begin mass scaling` (solver/setup/mass_scaling.hpp), after plastic_dissipation.
HistoryColumn mass_scaling_column() {
  HistoryColumn c = derived("added_mass", "kg",
                            "mass added by mass scaling (begin mass scaling), whole model; set once at set-up",
                            [](const S& s) { return s.added_mass; });
  c.mass_scaling_only = true;
  return c;
}

// The table. File order is the order here; existing scripts read columns by name, so a new column
// goes at the end (or behind a condition, like plastic_dissipation). Built on first use, after the
// field tables it points into.
std::vector<HistoryColumn> make_columns() {
  return {
      derived("time", "s", "simulated time t^n", [](const S& s) { return s.time; }),
      derived("dt", "s", "time step of the step that ended at t^n", [](const S& s) { return s.dt; }),
      energy("kinetic_energy", "kinetic"),
      energy("internal_energy", "internal"),
      energy("hourglass_energy", "hourglass"),
      energy("external_work", "external_work"),
      energy("silent_boundary_dissipation", "silent_boundary_dissipation"),
      energy("contact_work", "contact_work"),
      derived("energy_error", "-", "|energy balance| / largest energy of the run (docs/theory.md 1.3)",
              [](const S& s) { return s.energies.relative_error(); }),
      contact("contact_normal_force", "normal_force"),
      contact("contact_tangential_force", "tangential_force"),
      contact("contact_area", "area"),
      contact("contact_nodes", "nodes"),
      energy("damping_dissipation", "damping_dissipation"),
      energy("viscous_dissipation", "viscous_dissipation"),
      derived("contact_radius", "m",
              "contact radius, best estimate: contact_radius_edge where it is defined (a contact axis is set and the "
              "contact zone has a boundary on the slave surface), else contact_radius_area",
              [](const S& s) { return best_radius(s.contact); }),
      contact("contact_radius_max", "radius_max"),
      contact("contact_max_penetration", "max_penetration"),
      derived("momentum_x", "kg m/s", "sum m v^n, x", [](const S& s) { return s.momentum[0]; }),
      derived("momentum_y", "kg m/s", "sum m v^n, y", [](const S& s) { return s.momentum[1]; }),
      derived("momentum_z", "kg m/s", "sum m v^n, z", [](const S& s) { return s.momentum[2]; }),
      contact("contact_radius_edge", "radius_edge"),
      contact("adhesive_force", "adhesive_force"),
      contact("compressive_force", "compressive_force"),
      derived("friction_force", "N",
              "magnitude of the vector sum of the tangential contact forces: junction shear or Coulomb friction "
              "(as contact_tangential_force)",
              [](const S& s) { return s.contact.tangential_force; }),
      contact("tau_star_times_area", "junction_capacity"),
      contact("adhesion_energy", "adhesion_energy"),
      contact("friction_power", "friction_power"),
      contact("contact_radius_pressure_fit", "radius_pressure_fit"),
      contact("real_contact_area", "real_area"),
      contact("asperity_contacts", "asperity_contacts"),
      derived("apparent_pressure", "Pa", "rough-surface law: normal force over the nominal area within reach of the law",
              [](const S& s) { return s.contact.apparent_pressure(); }),
      derived("contact_radius_area", "m",
              "area estimator: sqrt(contact_area / pi), the radius of a disc of the nodal contact area; steps as node "
              "rings enter and reads high (3-10 % on the Hertz decks)",
              [](const S& s) { return area_radius(s.contact); }),
      energy("plastic_dissipation", "plastic_dissipation", true),
      mass_scaling_column(),
  };
}

}  // namespace

std::span<const HistoryColumn> history_columns() {
  static const std::vector<HistoryColumn> columns = make_columns();
  return columns;
}

std::vector<ColumnInfo> describe_history_columns(bool material_dissipation, const std::vector<std::string>& reaction_sets,
                                                 const std::vector<std::string>& displacement_sets,
                                                 bool mass_scaling) {
  std::vector<ColumnInfo> out{{"step", "count", "step index n"}};
  for (const HistoryColumn& c : history_columns())
    if (c.present(material_dissipation, mass_scaling))
      out.push_back({std::string(c.name), std::string(c.unit), std::string(c.definition)});
  for (const auto& set : reaction_sets)
    for (const char* i : {"x", "y", "z"})
      out.push_back({set + "_reaction_" + i, "N", std::string("sum of the reaction forces at the nodes of node set '") +
                                                       set + "', " + i});
  for (const auto& set : displacement_sets)
    for (const char* i : {"x", "y", "z"})
      out.push_back({set + "_displacement_" + i, "m", std::string("mean displacement of the nodes of node set '") +
                                                           set + "', " + i});
  return out;
}

}  // namespace tribex::solver
