// SPDX-License-Identifier: MIT
// The tables of the data structs that runs write (solver/output/field_table.hpp): each struct's
// fields once, with unit and definition, in the order restart files keep them. They drive
//   energy_fields()         restart ("energies"), summary.json "energies", history.csv's energy columns;
//   contact_total_fields()  restart ("contact_totals"), history.csv's contact columns;
//   warning_fields()        restart (the guards' warnings), summary.json "warnings";
//   rank_count_fields()     summary.json "rank_counts" (one object per MPI rank);
//   summary_fields()        summary.json, its keys in file order, and its "units" object.
// A new field is a new row. Restart files keep the rows that have a setter as one array per struct,
// by position: append a row at the end of its table (a restart file written before then is refused
// with the count of values it has and the count this tribex keeps).
#pragma once

#include <span>

#include "contact/contact_manager.hpp"
#include "solver/energy.hpp"
#include "solver/guards/run_warning.hpp"
#include "solver/output/field_table.hpp"
#include "solver/output/run_summary.hpp"

namespace tribex::solver {

std::span<const Field<Energies>> energy_fields();
std::span<const Field<contact::ContactTotals>> contact_total_fields();
std::span<const Field<RunWarning>> warning_fields();
std::span<const Field<parallel::RankCounts>> rank_count_fields();
std::span<const Field<RunSummary>> summary_fields();

}  // namespace tribex::solver
