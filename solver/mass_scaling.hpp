// SPDX-License-Identifier: MIT
// Selective (element-wise) mass scaling, `begin mass scaling` (docs/theory.md 1.4.1; LS-DYNA DT2MS < 0,
// Sierra/SM "begin mass scaling"). At set-up, from the reference stable-step estimate dt_e of every
// element (solver/stable_time_step.hpp, before the time step scale factor f):
//   element target   T_e = dt_target / f                  (dt_target: the run's step, s)
//   density factor   s_e = max(1, (T_e / dt_e)^2)         (dimensionless; dt_e ~ sqrt(rho) => dt_e' = T_e)
//   added mass       dm_e = (s_e - 1) rho V0_e             (kg, lumped as dm_e / 8 to each node)
// for the elements of the listed blocks; every other element keeps its mass. The factor is kept per
// element (ElementBlock::mass_scale) so that the stable step recomputed on the current configuration
// uses the scaled density, and the scaled lumped mass is in Model::mass before the contact is set up,
// so the contact is built on the scaled masses and step. The contact surface nodes then get (dt/dt_0)^2
// their unscaled mass, so the unscaled deck's penalty and their own elements meet the scaled step as
// they met the unscaled one (raise_contact_node_masses).
#pragma once

#include <string>
#include <vector>

#include "inputs/deck.hpp"

namespace tribex::solver {

struct Model;

/// s_e = max(1, (element_target / element_dt)^2): the density factor that brings an element's stable
/// step up to the target (elements at or above it keep 1).
double mass_scale_factor(double element_dt, double element_target);

struct BlockMassScaling {
  std::string name;
  bool listed = false;       // in the deck's `blocks` (or every block)
  int elements = 0;
  int scaled_elements = 0;   // elements with s_e > 1
  double mass = 0.0;         // unscaled, kg
  double added_mass = 0.0;   // kg
  double largest_scale = 1.0;  // max s_e
  double fraction() const { return mass > 0.0 ? added_mass / mass : 0.0; }
};

/// What the set-up did (the log, `tribex check`, summary.json "mass_scaling", the history column
/// added_mass).
struct MassScalingReport {
  bool active = false;
  double target_time_step = 0.0;    // the run's step, s
  double unscaled_time_step = 0.0;  // the run's step without mass scaling, s
  double unscaled_mass = 0.0;       // kg, the whole model
  double added_mass = 0.0;          // kg, the whole model
  double maximum_added_mass_fraction = 0.05;
  std::vector<BlockMassScaling> blocks;
  // The contact surface nodes raised to contact_mass_factor x their unscaled mass (raise_contact_node_masses):
  int contact_nodes = 0;             // surface nodes raised (over the ranks)
  double contact_mass_factor = 1.0;  // (dt / dt_0)^2
  double contact_added_mass = 0.0;   // kg, included in added_mass
  double added_fraction() const { return unscaled_mass > 0.0 ? added_mass / unscaled_mass : 0.0; }
  bool exceeds_limit() const { return active && added_fraction() > maximum_added_mass_fraction; }
  /// The set-up report, one line each.
  std::vector<std::string> lines() const;
  /// The numerical-failure message when exceeds_limit().
  std::string limit_message() const;
};

/// Scale the model's element densities and lumped masses as `spec` asks. `time_step_scale_factor`
/// and `maximum_time_step` are the time control's. Throws SetupError (deck line, what to change) for
/// an unknown block, a target below the unscaled step or above `maximum time step`. Call before the
/// contact is built (its penalty reads the masses and the step).
MassScalingReport apply_mass_scaling(const inputs::MassScalingSpec& spec, double time_step_scale_factor,
                                     double maximum_time_step, Model& model);

/// Set-up warning (issue 51): a silent boundary (docs/theory.md 4) whose faces lie on mass-scaled elements.
/// Its dashpots keep the physical impedance rho c, the scaled element's is sqrt(s) rho c, so a normally
/// incident wave reflects (sqrt(s) - 1) / (sqrt(s) + 1) of its amplitude there. Adds one warning per such
/// boundary to model.setup (counts over the ranks), naming the side set, the block and what to change.
void warn_scaled_silent_boundaries(const std::vector<inputs::SilentBoundarySpec>& boundaries, Model& model);

/// Contact consistency (docs/theory.md 1.4.1): every contact surface node gets at least `factor` times
/// its unscaled lumped mass; the model set-up passes factor = (dt / dt_0)^2, dt the scaled run's step and
/// dt_0 the unscaled one, so that each surface node's k dt^2 / m, for the unscaled penalty k and for the
/// stiffness of its own elements alike, is at most the unscaled run's: a deck whose contact is clean
/// unscaled stays clean scaled. A surface node whose elements were scaled less than that (a soft coating
/// whose own step is above the target) would otherwise meet the unscaled penalty at the larger step with
/// less headroom than unscaled, and chatter (issue 51: 3.4 % energy error at factor 2 with the earlier
/// raise to half of it). `nodes` the local indices of the surface nodes, each once; `mass` and
/// `unscaled_mass` [node] summed over the ranks; `owned` [node] the ownership weights. Returns the
/// added mass of the owned nodes (kg) and the number of owned nodes raised.
struct ContactMassRaise {
  double added_mass = 0.0;
  int nodes = 0;
};
ContactMassRaise raise_contact_node_masses(const std::vector<int>& nodes, const std::vector<double>& unscaled_mass,
                                           double factor, const std::vector<double>& owned, std::vector<double>& mass);

}  // namespace tribex::solver
