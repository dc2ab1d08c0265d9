// SPDX-License-Identifier: MIT
#include "solver/output/history_columns.hpp"

#include <cmath>

namespace tribex::solver {
namespace {

using S = HistoryState;

// The table. File order is the order here; existing scripts read columns by name, so a new column
// goes at the end (or behind a condition, like plastic_dissipation).
const HistoryColumn kColumns[] = {
    {"time", "s", "simulated time t^n", [](const S& s) { return s.time; }},
    {"dt", "s", "time step of the step that ended at t^n", [](const S& s) { return s.dt; }},
    {"kinetic_energy", "J", "(1/2) sum m |v^n|^2 (docs/theory.md 1.3)", [](const S& s) { return s.energies.kinetic; }},
    {"internal_energy", "J", "stored elastic strain energy, sum V0 W", [](const S& s) { return s.energies.internal; }},
    {"hourglass_energy", "J", "stored energy of the hourglass stiffness (mean quadrature)",
     [](const S& s) { return s.energies.hourglass; }},
    {"external_work", "J", "work of the reactions at constrained dofs and of the applied loads",
     [](const S& s) { return s.energies.external_work; }},
    {"silent_boundary_dissipation", "J", "energy absorbed by the silent-boundary dashpots",
     [](const S& s) { return s.energies.silent_boundary_dissipation; }},
    {"contact_work", "J", "work absorbed by the contact (minus the work of contact forces on the bodies)",
     [](const S& s) { return s.energies.contact_work; }},
    {"energy_error", "-", "|energy balance| / largest energy of the run (docs/theory.md 1.3)",
     [](const S& s) { return s.energies.relative_error(); }},
    {"contact_normal_force", "N", "net normal force on the slave nodes, compressive - adhesive",
     [](const S& s) { return s.contact.normal_force; }},
    {"contact_tangential_force", "N", "magnitude of the vector sum of junction shear forces",
     [](const S& s) { return s.contact.tangential_force; }},
    {"contact_area", "m^2", "tributary areas of the slave nodes in contact (junction: in-contact face parts)",
     [](const S& s) { return s.contact.area; }},
    {"contact_nodes", "count", "slave nodes in contact", [](const S& s) { return double(s.contact.nodes); }},
    {"damping_dissipation", "J", "energy dissipated by mass-proportional damping",
     [](const S& s) { return s.energies.damping_dissipation; }},
    {"viscous_dissipation", "J", "energy dissipated by bulk and hourglass viscosity",
     [](const S& s) { return s.energies.viscous_dissipation; }},
    {"contact_radius", "m",
     "sqrt(contact_area / pi): the nodal-area estimate, a node spacing coarse (contact_radius_pressure_fit "
     "or contact_radius_edge follow the Hertz radius closer)",
     [](const S& s) { return std::sqrt(s.contact.area / M_PI); }},
    {"contact_radius_max", "m", "distance from the contact axis of the farthest slave node in contact",
     [](const S& s) { return s.contact.radius_max; }},
    {"contact_max_penetration", "m", "deepest penetration of a slave node", [](const S& s) { return s.contact.max_penetration; }},
    {"momentum_x", "kg m/s", "sum m v^n, x", [](const S& s) { return s.momentum[0]; }},
    {"momentum_y", "kg m/s", "sum m v^n, y", [](const S& s) { return s.momentum[1]; }},
    {"momentum_z", "kg m/s", "sum m v^n, z", [](const S& s) { return s.momentum[2]; }},
    {"contact_radius_edge", "m",
     "mean distance from the axis of the points where the gap changes sign along slave-face edges",
     [](const S& s) { return s.contact.radius_edge; }},
    {"adhesive_force", "N", "sum of the attractive (adhesion) normal forces on the slave nodes",
     [](const S& s) { return s.contact.adhesive_force; }},
    {"compressive_force", "N", "sum of the repulsive (penalty) normal forces on the slave nodes",
     [](const S& s) { return s.contact.compressive_force; }},
    {"friction_force", "N", "magnitude of the vector sum of junction shear forces (as contact_tangential_force)",
     [](const S& s) { return s.contact.tangential_force; }},
    {"tau_star_times_area", "N", "junction strength tau* times the contact area", [](const S& s) { return s.contact.junction_capacity; }},
    {"adhesion_energy", "J", "adhesive potential sum A_I U(g_I) (<= 0)", [](const S& s) { return s.contact.adhesion_energy; }},
    {"friction_power", "W", "rate of energy dissipated by the junction shear", [](const S& s) { return s.contact.friction_power; }},
    {"contact_radius_pressure_fit", "m",
     "zero of the least-squares line p^2 = alpha - beta r^2 through the contacting nodes' pressures (the radius of "
     "an elliptic, Hertz-like, pressure)",
     [](const S& s) { return s.contact.radius_pressure_fit; }},
    {"real_contact_area", "m^2", "rough-surface law: real contact area sum A_I (A_c/A_0)",
     [](const S& s) { return s.contact.real_area; }},
    {"asperity_contacts", "count", "rough-surface law: asperities in contact sum A_I (N/A_0)",
     [](const S& s) { return s.contact.asperity_contacts; }},
    {"apparent_pressure", "Pa", "rough-surface law: normal force over the nominal area within reach of the law",
     [](const S& s) { return s.contact.apparent_pressure(); }},
    {"plastic_dissipation", "J", "work dissipated by the material updates (J2 plasticity), sum V0 sigma:deps_p",
     [](const S& s) { return s.energies.plastic_dissipation; }, true},
};

}  // namespace

std::span<const HistoryColumn> history_columns() { return kColumns; }

std::vector<ColumnInfo> describe_history_columns(bool material_dissipation, const std::vector<std::string>& reaction_sets,
                                                 const std::vector<std::string>& displacement_sets) {
  std::vector<ColumnInfo> out{{"step", "count", "step index n"}};
  for (const HistoryColumn& c : kColumns)
    if (!c.material_dissipation_only || material_dissipation)
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
