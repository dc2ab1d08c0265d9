// SPDX-License-Identifier: MIT
// Rigid bodies (`begin rigid body NAME`; Sierra/SM `rigid body`, Abaqus *COUPLING kinematic, LS-DYNA
// *CONSTRAINED_NODAL_RIGID_BODY): the nodes of a node set or a block move as one body with rotation fixed,
// so every node of it has the body's velocity. Set-up here: the node set NAME added to the mesh (so the
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

  std::size_t size() const { return name.size(); }
  bool empty() const { return name.empty(); }
};

/// Adds to `mesh` the node set NAME of every rigid body: the nodes of its block or a copy of its node set
/// (none where NAME is its own node set). SetupError (DECK:LINE: error: ... and the fix) for an unknown
/// block or node set, a NAME that names another node set, or a node in two bodies.
void add_rigid_body_node_sets(mesh::Mesh& mesh, const std::vector<inputs::RigidBodySpec>& bodies);

/// Collective: the bodies of `region` on this rank's model, once its masses are summed over the ranks and
/// its constraints and nodal forces are built. SetupError where a body's component is constrained on some
/// of its nodes only (a node-set condition on part of a body).
RigidBodies build_rigid_bodies(const inputs::RegionSpec& region, const Model& model);

/// The set-up report's lines: per body its nodes, mass, reference point and which components are driven.
std::vector<std::string> describe_rigid_bodies(const RigidBodies& bodies);

}  // namespace tribex::solver
