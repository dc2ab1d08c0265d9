// SPDX-License-Identifier: MIT
// CentralDifference state for restart files. A resumed run must repeat the uninterrupted one bit
// for bit, so every member that step() reads from an earlier step is saved exactly: the lagged
// halves of the trapezoidal energy rules, the stable-step estimate (recomputed only every
// dt_update_interval steps), the forces f^n of the last force pass, the element outputs of that
// pass and the contact search state. The energy ledger and the contact totals are kept as one array
// each, their fields in the order of their tables (solver/output/output_tables.hpp): a new member
// of Energies or ContactTotals is a row there (the history row after a resume is written from the
// restored values).
#include <string>
#include <vector>

#include "solver/integrators/central_difference.hpp"
#include "solver/output/output_tables.hpp"
#include "solver/restart/restart_remap.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {

void CentralDifference::save_state(StateArchive& a) const {
  a.put_integer("step", step_);
  a.put_integer("node_count", model_.mesh.node_count());
  a.put_integer("element_count", model_.mesh.element_count());
  // Global numbers, so that another rank count can resume from this file (restart_remap.hpp).
  a.put_ints("global_node", model_.domain.global_node);
  a.put_ints("global_element", model_.domain.global_element);
  std::vector<int> ranges;
  for (const auto& b : model_.blocks) ranges.insert(ranges.end(), {b.first_element, b.count});
  a.put_ints("block_ranges", ranges);
  a.put("time", time_);
  a.put("dt_n", dt_n_);
  a.put("dt_half", dt_half_);
  a.put("dt_prev_half", dt_prev_half_);
  a.put("stable_dt", stable_.dt);
  a.put_ints("stable_elements", std::vector<int>{stable_.controlling_element, stable_.inverted_element});
  a.put("u", u_);
  a.put("v_half", v_);
  a.put("v_prev_half", v_prev_);
  fill_reported_fields();
  a.put("v_n", v_n_);
  a.put("acceleration", a_);
  a.put("force", f_);
  a.put("external_force", f_ext_);
  a.put("reaction", reaction_);
  a.put("energies", stored_array(energy_fields(), energies_));
  std::vector<double> lagged;
  for (const double* member : lagged_members(*this)) lagged.push_back(*member);
  a.put("lagged_power", lagged);
  a.put("momentum", std::vector<double>(momentum_, momentum_ + 3));
  a.put("material_work", std::vector<double>{plastic_work_, force_time_});
  // The turning rigid bodies' motion at t^{n+1} (the same on every rank; none without such a body).
  if (model_.rigid_bodies.any_rotating()) a.put("rigid_motion", rigid_motion_.next);
  for (std::size_t b = 0; b < model_.blocks.size(); ++b) {
    a.put("block_" + std::to_string(b) + "_stress", model_.blocks[b].stress);
    if (!model_.blocks[b].state.empty()) a.put("block_" + std::to_string(b) + "_state", model_.blocks[b].state);
  }
  if (model_.contact) {
    a.put("contact_x", x_);
    a.put("contact_force", f_contact_);
    a.put("contact_totals", stored_array(contact_total_fields(), contact_totals_));
    const auto s = model_.contact->state();
    a.put("contact_traction", s.traction);
    a.put("contact_status", s.status);
    a.put_integer("contact_total_searches", s.total_searches);
    a.put_integer("contact_passes", static_cast<long long>(s.passes.size()));
    if (contact_region_) a.put_ints("contact_region", contact_region_->lists());
    for (std::size_t k = 0; k < s.passes.size(); ++k) {
      const std::string p = "contact_pass_" + std::to_string(k) + "_";
      a.put_ints(p + "candidate_offset", s.passes[k].candidate_offset);
      a.put_ints(p + "candidates", s.passes[k].candidates);
      a.put_ints(p + "last_face", s.passes[k].last_face);
      a.put(p + "x_at_search", s.passes[k].x_at_search);
      a.put(p + "gap", s.passes[k].gap);
      a.put_integer(p + "searched", s.passes[k].searched ? 1 : 0);
      a.put(p + "stable_dt", std::vector<double>{s.passes[k].stable_dt});
      if (!s.passes[k].law_state.empty()) a.put(p + "law_state", s.passes[k].law_state);
    }
  }
}

void CentralDifference::restore_state(const StateArchive& a) {
  if (a.integer("node_count") != model_.mesh.node_count() || a.integer("element_count") != model_.mesh.element_count())
    throw SetupError("the restart file holds " + std::to_string(a.integer("node_count")) + " nodes and " +
                     std::to_string(a.integer("element_count")) + " elements, the deck's mesh " +
                     std::to_string(model_.mesh.node_count()) + " and " + std::to_string(model_.mesh.element_count()) +
                     "; restart with the deck (and mesh) of the run that wrote it");
  step_ = static_cast<long>(a.integer("step"));
  time_ = a.scalar("time");
  dt_n_ = a.scalar("dt_n");
  dt_half_ = a.scalar("dt_half");
  dt_prev_half_ = a.scalar("dt_prev_half");
  stable_.dt = a.scalar("stable_dt");
  std::vector<int> se;
  a.get_ints("stable_elements", se);
  if (se.size() != 2) throw SetupError("restart file: 'stable_elements' must hold 2 values");
  stable_.controlling_element = se[0];
  stable_.inverted_element = se[1];
  a.get("u", u_);
  a.get("v_half", v_);
  a.get("v_prev_half", v_prev_);
  a.get("v_n", v_n_);
  a.get("acceleration", a_);
  reported_current_ = true;  // v_n and acceleration as reported for v_half's update (no refill)
  if (a.has("remapped_from_ranks")) {
    // Written by another rank count: this rank's share of the applied loads (a partial sum on shared
    // nodes) is formed again at the time of the last force pass, on the restored positions.
    force_time_ = a.array("material_work").at(1);
    apply_loads(force_time_);
  } else {
    a.get("external_force", f_ext_);
  }
  a.get("force", f_);
  a.get("reaction", reaction_);
  restore_array(energy_fields(), a.array("energies"), energies_, "the energy ledger");
  const auto members = lagged_members(*this);
  std::vector<double> lagged(members.size());
  a.get("lagged_power", lagged);
  for (std::size_t k = 0; k < members.size(); ++k) *members[k] = lagged[k];
  std::vector<double> p(3);
  a.get("momentum", p);
  for (int i = 0; i < 3; ++i) momentum_[i] = p[i];
  std::vector<double> material_work(2);
  a.get("material_work", material_work);
  plastic_work_ = material_work[0];
  force_time_ = material_work[1];
  if (model_.rigid_bodies.any_rotating()) {
    if (!a.has("rigid_motion"))
      throw SetupError("the restart file holds no rigid-body rotation, which this deck's turning rigid bodies need; "
                       "restart with the deck of the run that wrote it");
    a.get("rigid_motion", rigid_motion_.next);
    rigid_motion_.now = rigid_motion_.next;
  }
  for (std::size_t b = 0; b < model_.blocks.size(); ++b) {
    a.get("block_" + std::to_string(b) + "_stress", model_.blocks[b].stress);
    if (!model_.blocks[b].state.empty()) a.get("block_" + std::to_string(b) + "_state", model_.blocks[b].state);
  }
  if (model_.contact) {
    a.get("contact_x", x_);
    a.get("contact_force", f_contact_);
    restore_array(contact_total_fields(), a.array("contact_totals"), contact_totals_, "the contact totals");
    contact::ContactManager::State s;
    s.traction = a.array("contact_traction");
    s.status = a.array("contact_status");
    s.total_searches = static_cast<long>(a.integer("contact_total_searches"));
    s.passes.resize(static_cast<std::size_t>(a.integer("contact_passes")));
    for (std::size_t k = 0; k < s.passes.size(); ++k) {
      const std::string q = "contact_pass_" + std::to_string(k) + "_";
      a.get_ints(q + "candidate_offset", s.passes[k].candidate_offset);
      a.get_ints(q + "candidates", s.passes[k].candidates);
      a.get_ints(q + "last_face", s.passes[k].last_face);
      s.passes[k].x_at_search = a.array(q + "x_at_search");
      s.passes[k].gap = a.array(q + "gap");
      s.passes[k].searched = a.integer(q + "searched") != 0;
      s.passes[k].stable_dt = a.array(q + "stable_dt").at(0);
      if (a.has(q + "law_state")) s.passes[k].law_state = a.array(q + "law_state");
      // A distributed run's candidates belong to its region: without the region's lists (a file of
      // the replicated contact) every pass searches a new region at the first step, unless the lists
      // were moved here by slave node from another rank count (restart_remap.hpp): then the region is
      // built anew at the first step (region_stale_) and the passes search when they would have.
      if (contact_region_ && !a.has("contact_region") && !a.has("contact_candidates_moved")) s.passes[k].searched = false;
    }
    try {
      model_.contact->restore(s);
      if (a.has("contact_candidates_moved")) {
        model_.contact->keep_projected_candidates();
        region_stale_ = contact_region_ != nullptr;
      }
      if (contact_region_ && a.has("contact_region")) {
        std::vector<int> lists;
        a.get_ints("contact_region", lists);
        contact_region_->restore_lists(lists);
        model_.contact->set_present(contact_region_->present());
      }
    } catch (const std::invalid_argument& e) {
      throw SetupError(std::string("the restart file does not fit the deck's contact definition: ") + e.what());
    }
  } else if (a.reals.count("contact_x")) {
    throw SetupError("the restart file has contact state but the deck has no contact definition");
  }
}

RestartLayout CentralDifference::restart_layout() const {
  RestartLayout l;
  l.global_node = model_.domain.global_node;
  l.global_element = model_.domain.global_element;
  for (const auto& b : model_.blocks) {
    const int per_element = b.count > 0 ? static_cast<int>(b.state.size() / static_cast<std::size_t>(b.count)) : 0;
    const bool interleaved = b.formulation != inputs::ElementFormulation::mean_quadrature;
    // Interleaved records are padded to whole groups of four: the width per element is the state's
    // size per group over four (element_block.hpp, interleaved_size).
    const int width = interleaved && b.count > 0
                          ? static_cast<int>(b.state.size() / (static_cast<std::size_t>((b.count + interleave_width - 1) / interleave_width) * interleave_width))
                          : per_element;
    l.blocks.push_back({b.first_element, b.count, b.state.empty() ? 0 : width, interleaved});
  }
  l.node_fields = {"u", "v_half", "v_prev_half", "v_n", "acceleration", "force", "reaction"};
  l.reformed_node_fields = {"external_force"};
  if (model_.contact) {
    l.contact_global_node = model_.contact_global_node;
    for (std::size_t k = 0; k < model_.contact->pass_count(); ++k) {
      l.pass_slave_rows.push_back(model_.contact->pass_slave_nodes(k));
      l.pass_search_rows.push_back(l.pass_slave_rows.back());
      const auto& master = model_.contact->pass_master_nodes(k);
      l.pass_search_rows.back().insert(l.pass_search_rows.back().end(), master.begin(), master.end());
    }
    l.keep_candidates = model_.contact->node_to_face_only();
    l.contact_row_fields = {"contact_x", "contact_force", "contact_traction", "contact_status"};
  }
  // This rank's parts of sums over the ranks at the save point (between steps, after the force pass):
  // the element energies of that pass, its viscous power (lagged_members' index 1) and the plastic work.
  int stored = 0;
  for (const auto& f : energy_fields()) {
    if (!f.set) continue;
    if (f.name == "internal" || f.name == "hourglass") l.partial_sums.push_back({"energies", stored});
    ++stored;
  }
  l.partial_sums.push_back({"lagged_power", 1});
  l.partial_sums.push_back({"material_work", 0});
  return l;
}

}  // namespace tribex::solver
