// SPDX-License-Identifier: MIT
// Explicit central-difference time integration with half-step velocities (docs/theory.md 1.3), the
// only time-step loop of tribex. One call of step() advances n -> n+1:
//
//   dt^n      = (dt^{n-1/2} + dt^{n+1/2}) / 2            (dt^0 = dt^{1/2} / 2, v^{-1/2} = v^0)
//   v^{n+1/2} = v^{n-1/2} + dt^n M^{-1} f^n               free dofs
//             = [(m/dt^n - c/2) v^{n-1/2} + f^n] / (m/dt^n + c/2)
//                                                         dofs with dashpots / mass damping
//                                                         (semi-implicit, docs/theory.md 4.3),
//                                                         normal and tangential parts apart
//   v^{n+1/2} = prescribed                                constrained dofs; reaction
//   R^n       = m (v^{n+1/2} - v^{n-1/2}) / dt^n - f^n
//   -- time-n quantities complete: energies, history and field output at step n --
//   u^{n+1}   = u^n + dt^{n+1/2} v^{n+1/2}
//   f^{n+1}   = f_ext(t^{n+1}, x^{n+1}) - f_int(u^{n+1}, v^{n+1/2})
//   dt^{n+3/2} from the stable estimate on x^{n+1} (every `dt_update_interval` steps)
//
// Central difference is Newmark with beta = 0, gamma = 1/2 in this half-step form. The loop does no
// allocation: every array is sized in the constructor.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "inputs/deck.hpp"
#include "solver/energy.hpp"
#include "solver/integrators/step_sums.hpp"
#include "solver/model.hpp"
#include "solver/parallel/contact_region.hpp"
#include "solver/stable_time_step.hpp"

namespace tribex::solver {

struct StateArchive;
struct RestartLayout;

class CentralDifference {
 public:
  CentralDifference(Model& model, const inputs::TimeControlSpec& time_control);

  /// u^0 = 0, v^0 from the model (constrained dofs overwritten), f^0, dt^{1/2}. Throws SetupError
  /// when the stable step is not positive.
  void init();
  /// Advance one step; `on_time_n` is called after the time-n quantities are complete (velocity
  /// update, reactions, energies), before the positions move: the place for output.
  /// Throws NumericalFailure (with element/node, step and time) on NaN or an inverted element.
  void step(const std::function<void()>& on_time_n = {});
  /// Steps until the termination time, then close(); `on_time_n` as in step().
  void run(const std::function<void()>& on_time_n = {});
  /// Completes the time-n quantities at the current (final) time and reports them; the state is
  /// then final (no further step()).
  void close(const std::function<void()>& on_time_n = {});

  /// Restart (central_difference_state.cpp): the full state between two step() calls (time, step,
  /// step sizes, nodal kinematics and forces, energy ledger with its lagged halves, element
  /// outputs, contact state) into / from `archive`. restore_state() replaces init().
  void save_state(StateArchive& archive) const;
  void restore_state(const StateArchive& archive);
  /// What save_state writes per rank and how it maps to global numbers, for a resume on another rank
  /// count (solver/restart/restart_remap.hpp); an archive it remapped carries "remapped_from_ranks",
  /// and restore_state then forms the applied loads' nodal forces again from the loads at that time.
  RestartLayout restart_layout() const;

  bool finished() const { return time_ >= end_time_ * (1.0 - 1e-14) ; }

  // State at time n (valid inside on_time_n and after run()).
  long step_index() const { return step_; }
  double time() const { return time_; }
  double dt() const { return dt_n_; }                         // dt^n
  double next_dt() const { return dt_half_; }                 // dt^{n+1/2}
  const std::vector<double>& displacement() const { return u_; }
  const std::vector<double>& velocity_half() const { return v_; }  // v^{n+1/2}
  const std::vector<double>& velocity() const { fill_reported_fields(); return v_n_; }    // v^n
  const std::vector<double>& acceleration() const { fill_reported_fields(); return a_; }  // (v^{n+1/2} - v^{n-1/2}) / dt^n
  const std::vector<double>& force() const { return f_; }          // f^n, internal + applied loads
  const std::vector<double>& reaction() const { return reaction_; }  // R^n at constrained dofs, else 0
  /// [rigid-body entry][3] the coupling force g_i = m_i (V - v_i) / dt^n that gave node i its body's
  /// velocity V at the last update (free components; 0 on driven ones), N (Model::rigid_bodies).
  const std::vector<double>& rigid_coupling_force() const { return rigid_coupling_; }
  /// The turning rigid bodies' motion (solver/setup/rigid_bodies.hpp RigidMotion): `now` at time n.
  const RigidMotion& rigid_motion() const { return rigid_motion_; }
  const Energies& energies() const { return energies_; }
  const contact::ContactTotals& contact_totals() const { return contact_totals_; }  // at time n
  /// [surface node][3] positions in the contact's numbering at the last force pass (time n), m.
  const std::vector<double>& contact_positions() const { return x_; }
  const double* momentum() const { return momentum_; }  // sum m v^n, kg m/s
  double contact_seconds() const { return contact_seconds_; }  // wall time spent in contact so far
  const StableStep& stable_step() const { return stable_; }
  double time_step_scale_factor() const { return scale_factor_; }
  /// Set by the driver: does the step that reaches (t, n) write element fields? Element stresses
  /// are then computed in the force pass that precedes it.
  void set_stress_request(std::function<bool(double, long)> wants) { wants_stress_ = std::move(wants); }

 private:
  /// want_stable_step: the element pass also gives the stable step at this u (folded_stable_).
  void compute_forces(double t, bool want_stress, bool want_stable_step);
  // compute_forces' steps, in order:
  void apply_loads(double t);
  void add_element_forces(double t, bool want_stress, bool want_stable_step);
  void add_contact_forces();
  // account_time_n's steps, in order (each adds this rank's part to the step's sums):
  void sum_node_terms(StepSums& sums) const;
  void sum_load_power(StepSums& sums) const;
  void sum_contact_power(StepSums& sums) const;
  void sum_silent_power(StepSums& sums) const;
  void reduce_over_ranks(StepSums& sums);
  void fail_on_non_finite_velocity();
  void add_step_to_ledger(const StepSums& sums);
  /// What step() reads from the step before besides the nodal arrays: the right halves of the
  /// trapezoidal rules, the last pass's viscous power and the contact's wall time. Restart files keep
  /// them as "lagged_power" in this order (central_difference_state.cpp saves and restores by it).
  template <class Self>
  static auto lagged_members(Self& self) {
    return std::array{&self.external_power_right_, &self.viscous_power_,       &self.silent_power_right_,
                      &self.damping_power_right_,  &self.viscous_power_right_, &self.contact_power_right_,
                      &self.contact_seconds_};
  }
  bool stable_step_due() const { return step_ % dt_update_interval_ == 0 || stable_.dt <= 0.0; }
  void update_velocity();
  /// Rigid bodies (solver/setup/rigid_bodies.hpp): the free components of each body's nodes set to the
  /// body's velocity, its momentum over its mass (collective). `record`: keep the coupling forces.
  void move_rigid_bodies(bool record);
  /// The turning ones (central_difference_rigid.cpp, docs/theory.md 1.6): the rigid velocity nearest the
  /// nodes' (the drives and held axes imposed), the body's motion advanced to t^{n+1}, and each node's
  /// velocity the chord to its place there, so the body stays rigid to round-off.
  void move_turning_bodies(bool record);
  /// The turning bodies' (velocity, angular velocity) q = (V, omega) from their nodes' momentum b = (P, L):
  /// the drives' values at this step, the rest solved (solver/setup/rigid_bodies.hpp solve_rigid_velocity).
  void solve_turning_velocity(std::size_t body, bool record, const double b[6], double q[6]) const;
  /// The driven turning bodies' coupling forces in the work ledger, as constraint reactions are.
  void sum_rigid_drive_power(StepSums& sums) const;
  void apply_constraints();
  void account_time_n();
  /// v^n and a^n from v^{n-1/2} and v^{n+1/2}, once per velocity update and only when asked for
  /// (output steps, restart files): the step loop itself needs v^n only in registers.
  void fill_reported_fields() const;
  double choose_dt();
  /// Parallel runs: a rank that met a numerical failure keeps stepping to the next collective
  /// point; there every rank learns of it and throws, the message coming from the lowest failing
  /// rank. On one rank this throws at once.
  void raise_pending_failure();
  int global_element(int local) const { return local < 0 ? local : model_.domain.global_element[local]; }

  Model& model_;
  double end_time_, scale_factor_;
  double max_dt_;
  int dt_update_interval_ = 10;
  long step_ = 0;
  double time_ = 0.0;
  double dt_n_ = 0.0, dt_half_ = 0.0, dt_prev_half_ = 0.0;
  std::vector<double> u_, v_, v_prev_, f_, f_ext_, reaction_;
  mutable std::vector<double> v_n_, a_;      // reported v^n, a^n (fill_reported_fields)
  mutable bool reported_current_ = false;    // v_n_, a_ belong to the current velocity update
  bool reported_first_step_ = true;          // that update was step 0's (v^0 = v^{-1/2})
  std::vector<int> loaded_dofs_;             // dofs that nodal forces or pressures load, ascending
  std::vector<double> rigid_momentum_;       // [body][3] sum m v over a body (move_rigid_bodies)
  std::vector<double> rigid_coupling_;       // [rigid-body entry][3] N
  std::vector<double> rigid_turning_sums_;   // [body][6] sum m v, sum m r x v over a turning body
  RigidMotion rigid_motion_;
  std::vector<double> inverse_mass_;
  std::vector<double> owned_mass_;  // [local node] mass where this rank owns the node, else 0 (energy sums)
  // Mass damping on mass-scaled models (Model::damping_mass; both empty otherwise): [local node] the damped
  // mass over the lumped mass, and the damped mass where this rank owns the node, else 0.
  std::vector<double> damping_share_, owned_damping_mass_;
  double damping_mass(std::size_t node) const {
    return model_.damping_mass.empty() ? model_.mass[node] : model_.damping_mass[node];
  }
  std::string pending_failure_;     // a numerical failure met on this rank, raised collectively
  std::vector<int> silent_index_;  // [node] index into model.silent, -1 if none (empty: no silent nodes)
  Energies energies_;
  StableStep stable_;
  StableStep folded_stable_;           // from the last force pass that was asked for it (local numbering)
  bool folded_stable_valid_ = false;   // consumed by choose_dt
  double external_power_right_ = 0.0;  // F_ext^{n-1} . v^{n-1/2}, for the trapezoidal work rule
  double viscous_power_ = 0.0;        // element viscous dissipation rate of the last force pass
  std::vector<double> viscous_force_;  // [node][3] this rank's elements' viscous forces of that pass (N); empty unless exact
  bool exact_viscous_dissipation_ = false;  // `viscous dissipation = exact` (time control)
  double plastic_work_ = 0.0;         // this rank's material dissipation so far (J), summed in account_time_n
  double force_time_ = 0.0;           // the time of the last force pass (the material updates' dt)
  double silent_power_right_ = 0.0, damping_power_right_ = 0.0, viscous_power_right_ = 0.0;
  // Contact: current positions of surface nodes, contact forces, totals, lagged contact power.
  // x_, v_contact_, f_other_contact_ (the summed non-contact forces) and f_contact_ are in the
  // contact's numbering ([surface node][3], Model::contact_global_node): this rank's rows, and in a
  // distributed run its region's ghost rows (contact_region_; other rows keep stale values).
  std::vector<double> x_, f_contact_, v_contact_, f_other_contact_;
  std::unique_ptr<parallel::ContactRegion> contact_region_;
  // Resumed from a file of another rank count with the candidate lists moved by node: the region is
  // built at the first force pass (a collective step every rank reaches), without a search.
  bool region_stale_ = false;
  void complete_contact_forces();
  contact::ContactTotals contact_totals_;
  double momentum_[3] = {0, 0, 0};
  double contact_seconds_ = 0.0;
  double contact_power_right_ = 0.0;
  std::function<bool(double, long)> wants_stress_;
};

}  // namespace tribex::solver
