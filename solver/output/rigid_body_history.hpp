// SPDX-License-Identifier: MIT
// The history columns of the rigid bodies (`begin rigid body NAME`), after the node-set columns, in deck
// order: NAME_reaction_{x,y,z} (N), NAME_displacement_{x,y,z} (m), NAME_moment_{x,y,z} (N m), and for a body
// that turns (rotation free or driven) six more, NAME_rotation_{x,y,z} (rad, the rotation vector of Q: axis
// times angle) and NAME_angular_velocity_{x,y,z} (rad/s, at time n).
//
// The reaction is the force the reference point applies to the body: on every node i of it the coupling
// force c_i = g_i + R_i + s_i, where g_i is the rigid-body coupling force of a free component
// (CentralDifference::rigid_coupling_force, summing to zero), R_i the constraint reaction of a driven one
// and s_i the node's share of a prescribed force on the body. So a free component reports the prescribed
// force, a driven one the force that drives it (as `reaction force` on a node set). The moment is that of
// the c_i about the reference point, M = sum (x_i - x_ref) x c_i: with rotation fixed, the moment that
// holds the body from turning (a free body would turn under -M). The displacement is the body's (every
// node's) translation since t = 0. A turning body: the arm is the current one, Q (X_i - X_ref), so the
// moment is what drives or holds its rotation (zero about a free axis, up to the body's angular
// acceleration times its inertia), and the displacement that of its reference point.
#pragma once

#include <string>
#include <vector>

#include "solver/output/history_columns.hpp"
#include "solver/setup/rigid_bodies.hpp"

namespace tribex::solver {

struct Model;

/// The columns' descriptions, nine per body, fifteen per turning body.
std::vector<ColumnInfo> describe_rigid_body_columns(const RigidBodies& bodies);
/// The same for bodies named `bodies`, all turning or none (`tribex run --list-columns`).
std::vector<ColumnInfo> describe_rigid_body_columns(const std::vector<std::string>& bodies, bool turning);

/// What the columns are made from at time n (the integrator's arrays, this rank's local numbering).
struct RigidBodyState {
  double time = 0.0;                      // s: the prescribed forces' time
  const double* displacement = nullptr;   // [node][3] u^n
  const double* reaction = nullptr;       // [node][3] R^n, constraint reactions (0 off constrained dofs)
  const double* coupling = nullptr;       // [rigid-body entry][3] g_i
  const RigidMotion* motion = nullptr;    // the turning bodies' (required where a body turns)
};

/// Collective: the values of every body into `values` (sized as describe_rigid_body_columns by the caller).
void rigid_body_history_values(const Model& model, const RigidBodyState& state, std::vector<double>& values);

}  // namespace tribex::solver
