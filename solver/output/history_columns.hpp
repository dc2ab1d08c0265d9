// SPDX-License-Identifier: MIT
// The columns of history.csv as one table: name, SI unit, one-line definition and where the value
// comes from. The header, the row, the units file (history_columns.csv beside history.csv) and
// `tribex run --list-columns` are all made from it, so a column is added here and nowhere else.
// Node-set columns (<set>_reaction_{x,y,z}, <set>_displacement_{x,y,z}) follow the deck's
// `reaction force` / `mean displacement` lines and are described by node_set_column().
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contact/contact_manager.hpp"
#include "solver/energy.hpp"

namespace tribex::solver {

/// What a history row is made from at time n.
struct HistoryState {
  double time = 0.0;                      // s
  double dt = 0.0;                        // s
  const Energies& energies;
  const contact::ContactTotals& contact;
  const double* momentum = nullptr;       // [3], kg m/s
};

/// A column's description, as history_columns.csv lists it.
struct ColumnInfo {
  std::string name;
  std::string unit;        // SI; "-" for a pure number, "count" for a number of things
  std::string definition;  // one line
};

struct HistoryColumn {
  std::string_view name, unit, definition;
  double (*value)(const HistoryState&);
  bool material_dissipation_only = false;  // present only when a block's material dissipates
};

/// The standard columns in file order (after `step`).
std::span<const HistoryColumn> history_columns();

/// The descriptions of the standard columns present in a run, then of its node-set columns.
std::vector<ColumnInfo> describe_history_columns(bool material_dissipation, const std::vector<std::string>& reaction_sets,
                                                 const std::vector<std::string>& displacement_sets);

}  // namespace tribex::solver
