// SPDX-License-Identifier: MIT
#include "solver/integrators/central_difference.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>

#include "solver/errors.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/hex8/internal_forces.hpp"

namespace tribex::solver {
namespace {

std::string where_and_when(long step, double t) {
  char buf[96];
  std::snprintf(buf, sizeof buf, " at step %ld, t = %.6g s", step, t);
  return buf;
}

// Reported v^n = (v^{n-1/2} + v^{n+1/2})/2; at n = 0, v^0 = v^{-1/2}.
inline double velocity_at_n(bool first_step, double v_minus, double v_plus) {
  return first_step ? v_minus : 0.5 * (v_minus + v_plus);
}

// Kinetic energy (the shadow form), momentum and the mass-damping power halves over this rank's
// nodes, in one pass (account_time_n). Without mass damping its two sums are not formed: they are
// used only where it is on, and the rest is added in the same order either way (the same bits).
template <bool Damped>
void sum_over_nodes(bool first_step, std::size_t nodes, const double* v_minus, const double* v_plus,
                    const double* mass, const double* damped_mass, double& ke, double p[3], double& damp_left,
                    double& damp_right) {
  for (std::size_t n = 0; n < nodes; ++n) {
    const double m = mass[n], md = damped_mass[n];
    for (std::size_t d = 3 * n, i = 0; i < 3; ++d, ++i) {
      const double vn = velocity_at_n(first_step, v_minus[d], v_plus[d]);
      p[i] += m * vn;
      ke += 0.5 * m * v_minus[d] * v_plus[d];
      if constexpr (Damped) {
        damp_left += md * vn * v_minus[d];
        damp_right += md * vn * v_plus[d];
      }
    }
  }
}

}  // namespace

CentralDifference::CentralDifference(Model& model, const inputs::TimeControlSpec& tc)
    : model_(model),
      end_time_(tc.termination_time),
      scale_factor_(tc.time_step_scale_factor),
      max_dt_(tc.maximum_time_step.value_or(std::numeric_limits<double>::infinity())),
      time_(tc.start_time),
      exact_viscous_dissipation_(tc.exact_viscous_dissipation) {
  // A model assembled without build_model (tools, tests) runs as one rank.
  if (model.domain.owned.size() != model.mass.size()) model.domain.init_serial(model.mesh.node_count(), model.mesh.element_count());
  const std::size_t n3 = 3 * static_cast<std::size_t>(model.mesh.node_count());
  u_.assign(n3, 0.0);
  v_.assign(n3, 0.0);
  v_prev_.assign(n3, 0.0);
  v_n_.assign(n3, 0.0);
  a_.assign(n3, 0.0);
  f_.assign(n3, 0.0);
  f_ext_.assign(n3, 0.0);
  reaction_.assign(n3, 0.0);
  if (exact_viscous_dissipation_) viscous_force_.assign(n3, 0.0);
  if (model.contact) {
    const std::size_t s3 = 3 * model.contact_global_node.size();
    x_ = model.contact_reference;
    x_.resize(s3, 0.0);
    v_contact_.assign(s3, 0.0);
    f_other_contact_.assign(s3, 0.0);
    f_contact_.assign(s3, 0.0);
    model.domain.set_surface(model.contact_global_node);
    if (!model.domain.serial()) {
      // Distributed contact: this rank counts the surface nodes it owns and holds its region's.
      contact_region_ = std::make_unique<parallel::ContactRegion>(model.domain);
      const auto& owned = model.domain.surface_owned();
      model.contact->distribute(std::vector<char>(owned.begin(), owned.end()), contact_region_.get(), x_.data());
      contact_region_->set_fields(model.contact->ghost_fields());
    }
  }
  if (!model.silent.node.empty()) {
    silent_index_.assign(model.mass.size(), -1);
    for (std::size_t k = 0; k < model.silent.node.size(); ++k) silent_index_[model.silent.node[k]] = static_cast<int>(k);
  }
  inverse_mass_.resize(model.mass.size());
  for (std::size_t n = 0; n < model.mass.size(); ++n) inverse_mass_[n] = 1.0 / model.mass[n];
  owned_mass_.resize(model.mass.size());
  for (std::size_t n = 0; n < model.mass.size(); ++n) owned_mass_[n] = model.domain.owned[n] * model.mass[n];
  if (!model.damping_mass.empty()) {
    damping_share_.resize(model.mass.size());
    owned_damping_mass_.resize(model.mass.size());
    for (std::size_t n = 0; n < model.mass.size(); ++n) {
      damping_share_[n] = model.damping_mass[n] / model.mass[n];
      owned_damping_mass_[n] = model.domain.owned[n] * model.damping_mass[n];
    }
  }
  rigid_momentum_.assign(3 * model.rigid_bodies.size(), 0.0);
  rigid_coupling_.assign(3 * model.rigid_bodies.node.size(), 0.0);
  rigid_turning_sums_.assign(6 * model.rigid_bodies.size(), 0.0);
  rigid_motion_.init(model.rigid_bodies.size());
  for (const auto& load : model.nodal_forces) loaded_dofs_.insert(loaded_dofs_.end(), load.dof.begin(), load.dof.end());
  for (const auto& load : model.pressures)
    for (int node : load.face_nodes)
      for (int i = 0; i < 3; ++i) loaded_dofs_.push_back(3 * node + i);
  std::sort(loaded_dofs_.begin(), loaded_dofs_.end());
  loaded_dofs_.erase(std::unique(loaded_dofs_.begin(), loaded_dofs_.end()), loaded_dofs_.end());
}

void CentralDifference::fill_reported_fields() const {
  if (reported_current_) return;
  const double inverse_h = dt_n_ > 0.0 ? 1.0 / dt_n_ : 0.0;  // before the first update v^{+} = v^{-}: a = 0
  for (std::size_t d = 0; d < v_.size(); ++d) {
    v_n_[d] = velocity_at_n(reported_first_step_, v_prev_[d], v_[d]);
    a_[d] = (v_[d] - v_prev_[d]) * inverse_h;
  }
  reported_current_ = true;
}

void CentralDifference::raise_pending_failure() {
  if (model_.domain.serial()) {
    if (!pending_failure_.empty()) throw NumericalFailure(pending_failure_);
    return;
  }
  const double me = pending_failure_.empty() ? 1e9 : double(model_.domain.rank);
  const double first = parallel::min(me);
  if (first >= 1e9) return;
  std::string message = pending_failure_;
  parallel::broadcast(message, static_cast<int>(first));
  throw NumericalFailure(message);
}

double CentralDifference::choose_dt() {
  if (stable_step_due()) {
    // The force pass at this u has usually computed it already (bitwise the same numbers).
    stable_ = folded_stable_valid_ ? folded_stable_ : compute_stable_time_step(model_, u_.data());
    folded_stable_valid_ = false;
    stable_.controlling_element = global_element(stable_.controlling_element);
    if (stable_.inverted_element >= 0 && pending_failure_.empty())
      pending_failure_ = "element " + std::to_string(global_element(stable_.inverted_element) + 1) +
                         " inverted (non-positive volume)" + where_and_when(step_, time_);
    raise_pending_failure();
    if (!model_.domain.serial()) {
      // min over ranks; ties go to the lowest global element, as in the serial loop
      stable_.dt = parallel::min_location(stable_.dt, stable_.controlling_element);
    }
  }
  // Rough-surface contact springs A_I dp/dd bound the step too (none for the other models: the
  // penalty is scaled to the step); evaluated at the last contact force computation.
  const double contact_dt = model_.contact ? model_.contact->stable_time_step() : INFINITY;
  double dt = std::min(scale_factor_ * std::min(stable_.dt, contact_dt), max_dt_);
  // Land exactly on the termination time instead of overshooting it.
  if (time_ + dt > end_time_) dt = end_time_ - time_;
  return dt;
}

void CentralDifference::init() {
  v_ = model_.initial_velocity;
  // Constrained dofs start at their prescribed velocity (the displacement BCs take over at t^{1/2}).
  for (std::size_t k = 0; k < model_.constraints.dof.size(); ++k) {
    const int dof = model_.constraints.dof[k];
    using Kind = Constraints::Kind;
    const auto kind = model_.constraints.kind[k];
    if (kind == Kind::fixed) v_[dof] = 0.0;
    if (kind == Kind::velocity) v_[dof] = model_.constraints.scale[k] * model_.functions[model_.constraints.function[k]](time_);
  }
  move_rigid_bodies(false);  // a body starts with one velocity, its nodes' momentum over its mass
  v_prev_ = v_;
  double ke = 0.0;
  for (std::size_t d = 0; d < v_.size(); ++d) ke += 0.5 * owned_mass_[d / 3] * v_[d] * v_[d];
  parallel::sum(&ke, 1);
  const bool stress0 = wants_stress_ && wants_stress_(time_, 0);
  force_time_ = time_;
  stable_ = {};
  compute_forces(time_, stress0, true);
  energies_.kinetic = ke;
  dt_half_ = choose_dt();
  if (!(dt_half_ > 0.0))
    throw SetupError("the stable time step is not positive (" + std::to_string(dt_half_) + " s); check the mesh and materials");
}

void CentralDifference::compute_forces(double t, bool want_stress, bool want_stable_step) {
  std::fill(f_.begin(), f_.end(), 0.0);
  apply_loads(t);
  add_element_forces(t, want_stress, want_stable_step);
  force_time_ = t;
  // Partial nodal forces of shared nodes summed over the ranks that hold them.
  model_.domain.sum_shared(f_.data());
  raise_pending_failure();
  if (model_.contact) add_contact_forces();
}

// Applied pressures (follower loads on the current configuration) and prescribed nodal forces;
// f_ext is zero off the loaded dofs, so only those are cleared and copied.
void CentralDifference::apply_loads(double t) {
  if (loaded_dofs_.empty()) return;
  for (int d : loaded_dofs_) f_ext_[d] = 0.0;
  for (const auto& load : model_.nodal_forces) {
    const double f = load.scale * model_.functions[load.function](t);
    for (int dof : load.dof) f_ext_[dof] += f;
  }
  const auto& X = model_.mesh.coordinates;
  for (const auto& load : model_.pressures) {
    const double p = load.scale * model_.functions[load.function](t);
    for (std::size_t face = 0; face < load.face_nodes.size() / 4; ++face) {
      const int* n = &load.face_nodes[4 * face];
      double d1[3], d2[3];
      for (int i = 0; i < 3; ++i) {
        d1[i] = X[3 * n[2] + i] + u_[3 * n[2] + i] - X[3 * n[0] + i] - u_[3 * n[0] + i];
        d2[i] = X[3 * n[3] + i] + u_[3 * n[3] + i] - X[3 * n[1] + i] - u_[3 * n[1] + i];
      }
      // Area vector a = (d1 x d2)/2 (outward); each node takes -p a / 4.
      const double a[3] = {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]), 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                           0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
      for (int I = 0; I < 4; ++I)
        for (int i = 0; i < 3; ++i) f_ext_[3 * n[I] + i] -= 0.25 * p * a[i];
    }
  }
  for (int d : loaded_dofs_) f_[d] = f_ext_[d];
}

// The element pass, block by block: internal forces into f_, this rank's stored energies and
// dissipation rates, and (when asked) the stable step, folded in block order as
// compute_stable_time_step visits them.
void CentralDifference::add_element_forces(double t, bool want_stress, bool want_stable_step) {
  double strain = 0.0, hourglass = 0.0;
  viscous_power_ = 0.0;
  std::fill(viscous_force_.begin(), viscous_force_.end(), 0.0);
  hex8::StableStepMin stable;
  for (auto& blk : model_.blocks) {
    blk.viscous_force = exact_viscous_dissipation_ ? viscous_force_.data() : nullptr;
    const auto totals = add_internal_forces(blk, model_.mesh.connectivity.data(), model_.mesh.coordinates.data(), u_.data(),
                                            v_.data(), f_.data(), t - force_time_, want_stress, want_stable_step);
    if (want_stable_step) {
      if (totals.stable.dt < stable.dt) {
        stable.dt = totals.stable.dt;
        stable.controlling_element = totals.stable.controlling_element;
      }
      if (stable.inverted_element < 0) stable.inverted_element = totals.stable.inverted_element;
    }
    if (totals.first_inverted >= 0 && pending_failure_.empty())
      pending_failure_ = "element " + std::to_string(global_element(totals.first_inverted) + 1) + " of block '" +
                         blk.name + "' inverted (det F <= 0)" + where_and_when(step_ + 1, t);
    strain += totals.strain_energy;
    hourglass += totals.hourglass_energy;
    viscous_power_ += totals.viscous_power;
    plastic_work_ += totals.plastic_work;
  }
  if (want_stable_step) {
    folded_stable_ = {stable.dt, stable.controlling_element, stable.inverted_element};
    folded_stable_valid_ = true;
  }
  // This rank's parts; account_time_n sums them over the ranks.
  energies_.internal = strain;
  energies_.hourglass = hourglass;
}

// The contact runs in its own numbering (surface node k) on this rank's rows and, in a distributed
// run, the ghost rows of its region (parallel/contact_region.hpp); each rank adds the contact forces
// of the surface nodes it holds, complete there by the region's reach.
void CentralDifference::add_contact_forces() {
  const auto contact_start = std::chrono::steady_clock::now();
  const auto& X = model_.mesh.coordinates;
  const auto& local = model_.domain.surface_local();
  // f_ (internal + applied, summed over the ranks, no contact yet) and the last step size let the
  // junction shear predict the slip of the coming velocity update (contact/contact_manager.hpp, step 5).
  for (std::size_t k = 0; k < local.size(); ++k) {
    if (const int l = local[k]; l >= 0)
      for (int i = 0; i < 3; ++i) {
        x_[3 * k + i] = X[3 * l + i] + u_[3 * l + i];
        v_contact_[3 * k + i] = v_[3 * l + i];
        f_other_contact_[3 * k + i] = f_[3 * l + i];
      }
    for (int i = 0; i < 3; ++i) f_contact_[3 * k + i] = 0.0;
  }
  bool refreshed = false;
  if (contact_region_) {
    refreshed = model_.contact->plan_searches(x_.data());
    if (refreshed || region_stale_) {
      contact_region_->refresh(x_.data(), *model_.contact);
      model_.contact->set_present(contact_region_->present());
      region_stale_ = false;
    }
    contact_region_->fill_ghosts(x_.data(), v_contact_.data(), f_other_contact_.data());
  }
  contact_totals_ = model_.contact->compute_forces(x_.data(), v_contact_.data(), f_contact_.data(),
                                                   f_other_contact_.data(), dt_half_);
  // Until the next search only the ghost rows the passes read travel (owner computes: the nodes
  // near this rank's slave nodes, not the whole band of the region).
  if (refreshed && model_.contact->owner_computes()) contact_region_->trim(model_.contact->rows_read());
  if (contact_region_ && model_.contact->owner_computes()) complete_contact_forces();
  for (std::size_t k = 0; k < local.size(); ++k)
    if (const int l = local[k]; l >= 0)
      for (int i = 0; i < 3; ++i) f_[3 * l + i] += f_contact_[3 * k + i];
  // The nodes the totals name, in the whole mesh's numbering.
  const auto& whole = model_.contact_global_node;
  if (contact_totals_.penetration_node >= 0) contact_totals_.penetration_node = whole[contact_totals_.penetration_node];
  if (contact_totals_.motion_node >= 0) contact_totals_.motion_node = whole[contact_totals_.motion_node];
  contact_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - contact_start).count();
}

// Owner-computes contact: each slave node was computed on its owner only, so the forces on a node are
// spread over the ranks whose slave nodes touch it: summed over them (ContactRegion::sum_to_holders),
// so every holder has the whole force of its surface nodes.
void CentralDifference::complete_contact_forces() { contact_region_->sum_to_holders(f_contact_.data(), 3); }

void CentralDifference::update_velocity() {
  // dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2, and dt^{1/2}/2 on the first step.
  dt_n_ = step_ == 0 ? 0.5 * dt_half_ : 0.5 * (dt_prev_half_ + dt_half_);
  const double h = dt_n_;
  const double cm = model_.mass_damping;
  // The last half-step velocity moves to v_prev_ by a swap (no copy); every dof of v_ is
  // written below. The reported v^n and a^n are filled when asked for (fill_reported_fields).
  v_prev_.swap(v_);
  reported_first_step_ = step_ == 0;
  reported_current_ = false;
  // Per node, not per dof: no d / 3 in the loop.
  const std::size_t nodes = inverse_mass_.size();
  const double* v_minus = v_prev_.data();
  double* v_plus = v_.data();
  const double* force = f_.data();
  const double* inverse_mass = inverse_mass_.data();
  // (m/h + c m_d/2) v+ = (m/h - c m_d/2) v- + f, m_d the damped mass. Where m_d = m (no mass scaling)
  // keep and gain are the same for every node; without damping keep = 1 and gain = h exactly, so one
  // loop serves both (1 * v is exact: the same bits as v += h f / m).
  if (damping_share_.empty()) {
    const double keep = (1.0 - 0.5 * cm * h) / (1.0 + 0.5 * cm * h), gain = h / (1.0 + 0.5 * cm * h);
    for (std::size_t n = 0; n < nodes; ++n) {
      const double g = gain * inverse_mass[n];
      v_plus[3 * n] = keep * v_minus[3 * n] + g * force[3 * n];
      v_plus[3 * n + 1] = keep * v_minus[3 * n + 1] + g * force[3 * n + 1];
      v_plus[3 * n + 2] = keep * v_minus[3 * n + 2] + g * force[3 * n + 2];
    }
  } else {
    const double* share = damping_share_.data();
    for (std::size_t n = 0; n < nodes; ++n) {
      const double half_ch = 0.5 * cm * h * share[n], denominator = 1.0 / (1.0 + half_ch);
      const double keep = (1.0 - half_ch) * denominator, g = h * denominator * inverse_mass[n];
      v_plus[3 * n] = keep * v_minus[3 * n] + g * force[3 * n];
      v_plus[3 * n + 1] = keep * v_minus[3 * n + 1] + g * force[3 * n + 1];
      v_plus[3 * n + 2] = keep * v_minus[3 * n + 2] + g * force[3 * n + 2];
    }
  }
  // Silent-boundary nodes: semi-implicit dashpots, normal and tangential parts separately.
  const auto& sb = model_.silent;
  for (std::size_t k = 0; k < sb.node.size(); ++k) {
    const int n = sb.node[k];
    const double m = model_.mass[n];
    const double* nv = &sb.normal[3 * k];
    const double* vm = &v_prev_[3 * n];
    const double* f = &f_[3 * n];
    const double vn = vm[0] * nv[0] + vm[1] * nv[1] + vm[2] * nv[2];
    const double fn = f[0] * nv[0] + f[1] * nv[1] + f[2] * nv[2];
    const double cn = sb.c_normal[k] + cm * damping_mass(n), ct = sb.c_tangential[k] + cm * damping_mass(n);
    const double vn_new = ((m / h - 0.5 * cn) * vn + fn) / (m / h + 0.5 * cn);
    for (int i = 0; i < 3; ++i) {
      const double vt = vm[i] - vn * nv[i], ft = f[i] - fn * nv[i];
      const double vt_new = ((m / h - 0.5 * ct) * vt + ft) / (m / h + 0.5 * ct);
      v_[3 * n + i] = vn_new * nv[i] + vt_new;
    }
  }
  move_rigid_bodies(true);
}

// V = sum m_i v_i / M over a body's nodes (owned copies; one sum over the ranks), then v_i = V on every
// copy of its nodes, so all copies stay bit-identical. Each node's change is the coupling force
// g_i = m_i (V - v_i) / dt^n, which sums to zero over the body (docs/theory.md 1.6).
void CentralDifference::move_rigid_bodies(bool record) {
  const RigidBodies& rb = model_.rigid_bodies;
  if (rb.empty()) return;
  if (rb.any_rotating()) move_turning_bodies(record);
  std::fill(rigid_momentum_.begin(), rigid_momentum_.end(), 0.0);
  for (std::size_t b = 0; b < rb.size(); ++b)
    for (int k = rb.first[b]; k < rb.first[b + 1] && !rb.rotating[b]; ++k) {
      const int n = rb.node[k];
      const double w = rb.owned[k] * model_.mass[n];
      for (int i = 0; i < 3; ++i) rigid_momentum_[3 * b + i] += w * v_[3 * n + i];
    }
  if (!model_.domain.serial()) parallel::sum(rigid_momentum_.data(), static_cast<int>(rigid_momentum_.size()));
  const double inverse_h = record && dt_n_ > 0.0 ? 1.0 / dt_n_ : 0.0;
  for (std::size_t b = 0; b < rb.size(); ++b)
    for (int k = rb.first[b]; k < rb.first[b + 1] && !rb.rotating[b]; ++k) {
      const int n = rb.node[k];
      for (int i = 0; i < 3; ++i) {
        double& v = v_[3 * n + i];
        double& g = rigid_coupling_[3 * static_cast<std::size_t>(k) + i];
        if (!rb.free[3 * b + i]) {
          g = 0.0;
          continue;
        }
        const double V = rigid_momentum_[3 * b + i] / rb.mass[b];
        g = model_.mass[n] * (V - v) * inverse_h;
        v = V;
      }
    }
}

void CentralDifference::apply_constraints() {
  using Kind = Constraints::Kind;
  const auto& c = model_.constraints;
  const double t_half = time_ + 0.5 * dt_half_, t_next = time_ + dt_half_;
  for (std::size_t k = 0; k < c.dof.size(); ++k) {
    const int dof = c.dof[k];
    double v = 0.0;
    if (c.kind[k] == Kind::velocity) v = c.scale[k] * model_.functions[c.function[k]](t_half);
    if (c.kind[k] == Kind::displacement)
      v = dt_half_ > 0.0 ? (c.scale[k] * model_.functions[c.function[k]](t_next) - u_[dof]) / dt_half_ : 0.0;
    v_[dof] = v;
  }
  // R^n = m (v^{n+1/2} - v^{n-1/2}) / dt^n - f^n - F_damp^n: the constraint also balances the mass
  // damping and dashpot forces (-C v^n) acting on the constrained dof, which the dissipation
  // terms count; leaving them out would put their work in neither ledger.
  const auto& sb = model_.silent;
  for (int dof : c.dof) {
    const int node = dof / 3, i = dof % 3;
    const double m = model_.mass[node];
    const double vbar = 0.5 * (v_[dof] + v_prev_[dof]);
    double damping = -model_.mass_damping * damping_mass(node) * vbar;
    if (const int k = silent_index_.empty() ? -1 : silent_index_[node]; k >= 0) {
      const double* nv = &sb.normal[3 * k];
      double vn = 0.0;
      for (int j = 0; j < 3; ++j) vn += 0.5 * (v_[3 * node + j] + v_prev_[3 * node + j]) * nv[j];
      damping -= sb.c_normal[k] * vn * nv[i] + sb.c_tangential[k] * (vbar - vn * nv[i]);
    }
    reaction_[dof] = m * (v_[dof] - v_prev_[dof]) / dt_n_ - f_[dof] - damping;
  }
}

void CentralDifference::account_time_n() {
  StepSums sums;
  sum_node_terms(sums);
  sum_load_power(sums);
  if (model_.contact) sum_contact_power(sums);
  sum_silent_power(sums);
  sums.internal = energies_.internal;
  sums.hourglass = energies_.hourglass;
  sums.viscous_power = viscous_power_;
  // The right half F_v^n . v^{n+1/2}: this rank's elements' forces (not exchanged) on its copies of
  // their nodes, so that the sum over the ranks counts each element once.
  // Without `viscous dissipation = exact` the right half is taken equal to the left (O(dt^2) per step).
  if (exact_viscous_dissipation_)
    for (std::size_t d = 0; d < v_.size(); ++d) sums.viscous_right -= viscous_force_[d] * v_[d];
  else
    sums.viscous_right = viscous_power_;
  sums.plastic_work = plastic_work_;
  reduce_over_ranks(sums);
  momentum_[0] = sums.momentum_x;
  momentum_[1] = sums.momentum_y;
  momentum_[2] = sums.momentum_z;
  energies_.internal = sums.internal;
  energies_.hourglass = sums.hourglass;
  viscous_power_ = sums.viscous_power;
  energies_.plastic_dissipation = sums.plastic_work;
  if (!std::isfinite(sums.kinetic)) fail_on_non_finite_velocity();
  energies_.kinetic = sums.kinetic;
  add_step_to_ledger(sums);
}

// Kinetic energy in the form the central-difference scheme conserves exactly for linear problems,
// KE^n = (1/2) v^{n-1/2} . M v^{n+1/2} (the "shadow" energy of the leapfrog), so the energy balance
// measures the model, not the averaging of v^n (at n = 0, v^{-1/2} = v^0); momentum; mass damping.
// Sums over nodes count each node once, on the rank that owns it (owned_mass_ is 0 elsewhere). One
// pass over the nodes for every all-node sum, per node, not per dof (no d / 3, d % 3); v^n in
// registers (velocity_at_n), no array written.
void CentralDifference::sum_node_terms(StepSums& s) const {
  const bool first_step = reported_first_step_;
  const std::size_t nodes = owned_mass_.size();
  const double* v_minus = v_prev_.data();
  const double* v_plus = v_.data();
  const double* mass = owned_mass_.data();
  const double* damped_mass = owned_damping_mass_.empty() ? mass : owned_damping_mass_.data();
  double p[3] = {0.0, 0.0, 0.0};
  if (model_.mass_damping > 0.0)
    sum_over_nodes<true>(first_step, nodes, v_minus, v_plus, mass, damped_mass, s.kinetic, p, s.damping_left, s.damping_right);
  else
    sum_over_nodes<false>(first_step, nodes, v_minus, v_plus, mass, damped_mass, s.kinetic, p, s.damping_left, s.damping_right);
  s.momentum_x = p[0];
  s.momentum_y = p[1];
  s.momentum_z = p[2];
}

// Work of the reactions and applied loads, in the pairing that makes the balance exact for the
// scheme: W^{n} - W^{n-1} = (1/2) v^{n-1/2} . (dt^{n-1} F^{n-1} + dt^n F^n), which with the shadow
// kinetic energy gives KE + IE = E0 + W to round-off for linear problems (also across the half first
// step and variable steps). The F^{n-1} half is kept from the last step (add_step_to_ledger).
void CentralDifference::sum_load_power(StepSums& s) const {
  const auto& owned = model_.domain.owned;
  for (int dof : model_.constraints.dof) {
    s.external_left += owned[dof / 3] * reaction_[dof] * v_prev_[dof];
    s.external_right += owned[dof / 3] * reaction_[dof] * v_[dof];
  }
  if (model_.rigid_bodies.any_rotating()) sum_rigid_drive_power(s);
  // f_ext is zero off the loaded dofs: summing over them alone gives the same bits.
  for (int d : loaded_dofs_) {
    s.external_left += f_ext_[d] * v_prev_[d];
    s.external_right += f_ext_[d] * v_[d];
  }
}

// Contact: the energy held or dissipated by the interface is minus the work of the contact forces
// on the bodies, in the same pairing.
void CentralDifference::sum_contact_power(StepSums& s) const {
  const auto& local = model_.domain.surface_local();
  const auto& surface_owned = model_.domain.surface_owned();
  for (std::size_t k = 0; k < local.size(); ++k) {
    const int l = local[k];
    if (l < 0) continue;
    for (int i = 0; i < 3; ++i) {
      s.contact_left += surface_owned[k] * f_contact_[3 * k + i] * v_prev_[3 * l + i];
      s.contact_right += surface_owned[k] * f_contact_[3 * k + i] * v_[3 * l + i];
    }
  }
}

// Dashpots: the force F^n = -C v^n (semi-implicit) enters the balance in the same pairing as the
// loads: through time n, all of F^{n-1} and the v^{n-1/2} half of F^n (docs/theory.md 4.3).
void CentralDifference::sum_silent_power(StepSums& s) const {
  const bool first_step = reported_first_step_;
  const auto& owned = model_.domain.owned;
  const auto& sb = model_.silent;
  for (std::size_t k = 0; k < sb.node.size(); ++k) {
    const int node = sb.node[k];
    const double* nv = &sb.normal[3 * k];
    const double* vl = &v_prev_[3 * node];
    const double* vr = &v_[3 * node];
    const double vb[3] = {velocity_at_n(first_step, vl[0], vr[0]), velocity_at_n(first_step, vl[1], vr[1]),
                          velocity_at_n(first_step, vl[2], vr[2])};
    const double bn = vb[0] * nv[0] + vb[1] * nv[1] + vb[2] * nv[2];
    const double ln = vl[0] * nv[0] + vl[1] * nv[1] + vl[2] * nv[2];
    const double rn = vr[0] * nv[0] + vr[1] * nv[1] + vr[2] * nv[2];
    const double bl = vb[0] * vl[0] + vb[1] * vl[1] + vb[2] * vl[2];
    const double br = vb[0] * vr[0] + vb[1] * vr[1] + vb[2] * vr[2];
    s.silent_left += owned[node] * (sb.c_normal[k] * bn * ln + sb.c_tangential[k] * (bl - bn * ln));
    s.silent_right += owned[node] * (sb.c_normal[k] * bn * rn + sb.c_tangential[k] * (br - bn * rn));
  }
}

// One reduction over the ranks for every sum of this step, in step_sum_fields' layout (no-op on one rank).
void CentralDifference::reduce_over_ranks(StepSums& s) {
  if (model_.domain.serial()) return;
  const auto start = std::chrono::steady_clock::now();
  std::array<double, step_sum_fields.size()> packed;
  for (std::size_t i = 0; i < packed.size(); ++i) packed[i] = s.*step_sum_fields[i];
  parallel::sum(packed.data(), static_cast<int>(packed.size()));
  for (std::size_t i = 0; i < packed.size(); ++i) s.*step_sum_fields[i] = packed[i];
  model_.domain.communication_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A kinetic energy that is not finite: the first node whose velocity is not, or (one rank) the energy.
void CentralDifference::fail_on_non_finite_velocity() {
  for (std::size_t d = 0; d < v_.size() && pending_failure_.empty(); ++d)
    if (!std::isfinite(v_[d]))
      pending_failure_ = "velocity of node " + std::to_string(model_.domain.global_node[d / 3] + 1) + " is not finite" +
                         where_and_when(step_, time_) +
                         " (instability: reduce the time step scale factor, check the loads and materials)";
  if (pending_failure_.empty() && model_.domain.serial()) pending_failure_ = "kinetic energy is not finite" + where_and_when(step_, time_);
  raise_pending_failure();
}

// The trapezoidal rules: this step's left halves with the last step's right halves (kept scaled by
// their step, h F^{n-1} . v^{n-1/2}), then this step's right halves kept for the next.
void CentralDifference::add_step_to_ledger(const StepSums& s) {
  const double h = dt_n_;
  if (step_ > 0) energies_.external_work += 0.5 * (external_power_right_ + h * s.external_left);
  external_power_right_ = h * s.external_right;
  if (model_.contact) {
    if (step_ > 0) energies_.contact_work -= 0.5 * (contact_power_right_ + h * s.contact_left);
    contact_power_right_ = h * s.contact_right;
  }
  if (step_ == 0) energies_.initial = energies_.kinetic + energies_.internal + energies_.hourglass;
  energies_.silent_boundary_dissipation += 0.5 * (silent_power_right_ + h * s.silent_left);
  silent_power_right_ = h * s.silent_right;
  if (model_.mass_damping > 0.0) {
    energies_.damping_dissipation += 0.5 * model_.mass_damping * (damping_power_right_ + h * s.damping_left);
    damping_power_right_ = h * s.damping_right;
  }
  // Element viscosity in the same pairing: -F_v^n . v^{n-1/2} is the kernels' power, -F_v^n . v^{n+1/2}
  // the kept viscous forces' (docs/theory.md 1.3). Taking the second equal to the first, as before,
  // is O(dt^2) per step, and not small where nodes ring near the step's frequency: the mu_T = 1
  // adhesion decks reported 1.5-2.7 % energy errors from it (verification/adhesion_transition).
  energies_.viscous_dissipation += 0.5 * (viscous_power_right_ + h * viscous_power_);
  viscous_power_right_ = h * s.viscous_right;
}

void CentralDifference::step(const std::function<void()>& on_time_n) {
  update_velocity();
  apply_constraints();
  account_time_n();
  if (on_time_n) on_time_n();

  // u^{n+1} = u^n + dt^{n+1/2} v^{n+1/2}
  const double h = dt_half_;
  for (std::size_t d = 0; d < u_.size(); ++d) u_[d] += h * v_[d];
  time_ += h;
  ++step_;
  const bool want_stress = wants_stress_ && wants_stress_(time_, step_);
  compute_forces(time_, want_stress, !finished() && stable_step_due());
  dt_prev_half_ = dt_half_;
  dt_half_ = finished() ? dt_prev_half_ : choose_dt();
  if (!finished() && dt_half_ < 1e-6 * dt_prev_half_)
    throw NumericalFailure("time step collapsed to " + std::to_string(dt_half_) + " s (element " +
                           std::to_string(stable_.controlling_element + 1) + " controls it)" + where_and_when(step_, time_));
}

void CentralDifference::run(const std::function<void()>& on_time_n) {
  while (!finished()) step(on_time_n);
  close(on_time_n);
}

void CentralDifference::close(const std::function<void()>& on_time_n) {
  // The final time N: complete v^N, reactions and energies with a last velocity update over the
  // previous step size (the positions do not move again), then report time N.
  update_velocity();
  apply_constraints();
  account_time_n();
  if (on_time_n) on_time_n();
}

}  // namespace tribex::solver
