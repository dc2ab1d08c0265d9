// SPDX-License-Identifier: MIT
// The columns of history.csv as one table: name, SI unit, one-line definition and where the value
// comes from. The header, the row, the units file (history_columns.csv beside history.csv) and
// `tribex run --list-columns` are all made from it, so a column is added here and nowhere else. A
// column that shows a field of Energies or ContactTotals takes its unit and definition from that
// field's row (solver/output/output_tables.hpp), so the two cannot disagree.
// Node-set columns (<set>_reaction_{x,y,z}, <set>_displacement_{x,y,z}) follow the deck's
// `reaction force` / `mean displacement` lines and are described by describe_history_columns().
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contact/contact_manager.hpp"
#include "solver/energy.hpp"
#include "solver/output/field_table.hpp"

namespace tribex::solver {

/// What a history row is made from at time n.
struct HistoryState {
  double time = 0.0;                      // s
  double dt = 0.0;                        // s
  const Energies& energies;
  const contact::ContactTotals& contact;
  const double* momentum = nullptr;       // [3], kg m/s
  double added_mass = 0.0;                // kg, mass scaling (constant over the run)
};

/// A column's description, as history_columns.csv lists it.
struct ColumnInfo {
  std::string name;
  std::string unit;        // SI; "-" for a pure number, "count" for a number of things
  std::string definition;  // one line
};

/// A column is a field of the energy ledger or of the contact totals (its unit and definition are
/// that field's row in solver/output/output_tables.cpp), or a value derived from the state.
struct HistoryColumn {
  std::string_view name, unit, definition;
  double (*derived)(const HistoryState&) = nullptr;
  const Field<Energies>* energy = nullptr;
  const Field<contact::ContactTotals>* contact = nullptr;
  bool material_dissipation_only = false;  // present only when a block's material dissipates
  bool mass_scaling_only = false;          // present only in a run with `begin mass scaling`

  bool present(bool material_dissipation, bool mass_scaling) const {
    return (!material_dissipation_only || material_dissipation) && (!mass_scaling_only || mass_scaling);
  }

  double value(const HistoryState& s) const {
    return energy ? energy->get(s.energies) : contact ? contact->get(s.contact) : derived(s);
  }
};

/// The standard columns in file order (after `step`).
std::span<const HistoryColumn> history_columns();

/// The descriptions of the standard columns present in a run, then of its node-set columns.
std::vector<ColumnInfo> describe_history_columns(bool material_dissipation, const std::vector<std::string>& reaction_sets,
                                                 const std::vector<std::string>& displacement_sets,
                                                 bool mass_scaling = false);

}  // namespace tribex::solver
