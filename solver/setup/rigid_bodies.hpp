// SPDX-License-Identifier: MIT
// Rigid bodies (`begin rigid body NAME`; Sierra/SM `rigid body`, Abaqus *COUPLING kinematic, LS-DYNA
// *CONSTRAINED_NODAL_RIGID_BODY): the nodes of a node set or a block move as one body. With rotation fixed
// and undriven every node of it has the body's velocity (below); a body that turns (`rotation = free`, or a
// `prescribed rotation | angular velocity` names it) moves by its reference point's velocity and its angular
// velocity, the last part of this header (docs/theory.md 1.6). Set-up here: the node set NAME added to the mesh (so the
// node-set boundary conditions reach every node of the body: `rigid body = NAME` in a prescribed
// displacement, velocity or force), and the per-body node lists the loop and the history read.
//
// The motion (docs/theory.md 1.6): each step, after the nodal velocity update, the free components of
// the body's nodes are replaced by the body's velocity V = sum m_i v_i / sum m_i (its momentum over its
// mass: the sum of the forces on its nodes, prescribed force included, over its mass; the projection
// also keeps damping per node consistent). A component a `prescribed displacement | velocity` drives
// is set on every node of the body by the existing constraints. The coupling forces
// g_i = m_i (V - v_i) / dt sum to zero over the body (momentum is kept) and do no work (every node has
// the velocity V), so the energy balance needs no new term.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "inputs/deck.hpp"
#include "mesh/mesh.hpp"

namespace tribex::solver {

struct Model;

/// The region's rigid bodies as struct of arrays, on this rank (local node numbers).
struct RigidBodies {
  std::vector<std::string> name;
  std::vector<int> first;            // [body + 1] offsets of each body's entries in `node`
  std::vector<int> node;             // [entry] the body's nodes this rank holds (owned and shared)
  std::vector<double> owned;         // [entry] 1 where this rank owns the node, else 0 (sums count it once)
  std::vector<int> node_count;       // [body] nodes of the whole model
  std::vector<double> mass;          // [body] kg, the lumped (and scaled) masses summed over the whole body
  std::vector<double> reference;     // [body][3] reference point at t = 0, m
  std::vector<unsigned char> free;   // [body][3] 1: the component moves by the forces; 0: a constraint drives it
  // Prescribed forces on the bodies: Model::nodal_forces[load_index[k]] acts on body load_body[k], component
  // load_component[k] (its per-node share is the load's scale times its function).
  std::vector<int> load_body, load_index, load_component;
  // Turning bodies (docs/theory.md 1.6). The others (rotating[b] = 0) keep the translation-only step above,
  // and their entries below stay zero.
  std::vector<unsigned char> rotating;  // [body] 1: rotation free about some axis, or driven
  std::vector<unsigned char> axis_free; // [body][3] 1: turns freely about the global axis through the reference point
  std::vector<double> arm;              // [entry][3] X_i - X_ref, m (the reference configuration)
  std::vector<double> first_moment;     // [body][3] S0 = sum m_i (X_i - X_ref), kg m
  std::vector<double> inertia;          // [body][9] J0 = sum m_i (|r_i|^2 1 - r_i r_i^T), r_i = X_i - X_ref, kg m^2
  // Drives of a turning body, [body][6]: translation x y z of the reference point, then rotation about x y z.
  // drive_kind 0: none (free, or a held axis); 1: displacement / angle; 2: velocity / angular velocity.
  std::vector<unsigned char> drive_kind;
  std::vector<int> drive_function;   // index into Model::functions
  std::vector<double> drive_scale;   // m, m/s, rad or rad/s per unit of the function

  std::size_t size() const { return name.size(); }
  bool empty() const { return name.empty(); }
  bool any_rotating() const {
    for (unsigned char r : rotating)
      if (r) return true;
    return false;
  }
  /// A turning body some drive moves: its coupling forces enter the work ledger like constraint reactions.
  bool driven(std::size_t b) const {
    for (int j = 0; j < 6; ++j)
      if (drive_kind[6 * b + j]) return true;
    return false;
  }
};

/// The motion of the turning bodies, [body][RigidMotion::size] each (identity for the others): the reference
/// point's displacement U (3), the rotation Q (9, row-major: x = X_ref + U + Q (X - X_ref)), the integral of
/// the angular velocity theta (3, the angle about a fixed axis), the angular velocity omega (3), and the
/// body's momentum P (3) and angular momentum L (3) about its centre of mass (docs/theory.md eq. 1.6.1).
/// `next` is U, Q, theta at t^{n+1} and omega, P, L at n+1/2; `now` the same one step before (t^n, n-1/2);
/// `omega_n` [body][3] the angular velocity at t^n, (omega^{n-1/2} + omega^{n+1/2}) / 2 (omega^0 = omega^{-1/2}).
struct RigidMotion {
  static constexpr int size = 24, U = 0, Q = 3, theta = 12, omega = 15, P = 18, L = 21;
  std::vector<double> now, next, omega_n;
  void init(std::size_t bodies);
};

/// The rotation matrix of the rotation vector theta (Rodrigues: R = 1 + sin|t| [n]x + (1 - cos|t|) [n]x^2,
/// n = t / |t|; docs/theory.md eq. 1.6.4), row-major.
void rotation_matrix(const double theta[3], double R[9]);
/// The rotation vector of a rotation matrix (the inverse of rotation_matrix for |theta| < pi), rad.
void rotation_vector(const double Q[9], double theta[3]);
/// The rigid velocity q = (V, omega) of a body (V the reference point's velocity) nearest, in the
/// kinetic-energy norm, to nodal velocities whose momentum is b = (P, L) (L about the reference point):
/// the rows of A q = b, A = [[M 1, -[S]x], [[S]x, J]] (docs/theory.md eq. 1.6.2), for the components not
/// known[j]; the known ones keep q[j]. S and J: the first moment and inertia about the reference point,
/// in the current configuration. The mass-weighted least-squares fit, so the change of the nodal velocities
/// has no momentum along the free components (no work, momentum kept).
void solve_rigid_velocity(double mass, const double S[3], const double J[9], const double b[6],
                          const unsigned char known[6], double q[6]);

/// Adds to `mesh` the node set NAME of every rigid body: the nodes of its block or a copy of its node set
/// (none where NAME is its own node set). SetupError (DECK:LINE: error: ... and the fix) for an unknown
/// block or node set, a NAME that names another node set, or a node in two bodies.
void add_rigid_body_node_sets(mesh::Mesh& mesh, const std::vector<inputs::RigidBodySpec>& bodies);

/// Collective: the bodies of `region` on this rank's model, once its masses are summed over the ranks and
/// its constraints and nodal forces are built. SetupError where a body's component is constrained on some
/// of its nodes only (a node-set condition on part of a body).
/// A turning body's nodes leave Model::constraints (its drives move them): SetupError where a node-set
/// condition constrains any of them.
RigidBodies build_rigid_bodies(const inputs::RegionSpec& region, Model& model);

/// The set-up report's lines: per body its nodes, mass, reference point and which components are driven.
std::vector<std::string> describe_rigid_bodies(const RigidBodies& bodies);

}  // namespace tribex::solver
