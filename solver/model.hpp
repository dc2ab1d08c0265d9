// SPDX-License-Identifier: MIT
// The discretised problem a run integrates: mesh, element blocks, lumped mass, kinematic
// constraints, loads and silent boundaries, all in flat arrays built once before the loop.
//
// Layouts: every nodal vector is [node][3] (x, y, z of node n at 3n..3n+2); a "dof" is 3n + c.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_manager.hpp"
#include "inputs/deck.hpp"
#include "mesh/generated_plan.hpp"
#include "mesh/mesh.hpp"
#include "solver/setup/contact_setup.hpp"
#include "solver/element_block.hpp"
#include "solver/guards/run_warning.hpp"
#include "solver/setup/mass_scaling.hpp"
#include "solver/setup/rigid_bodies.hpp"
#include "solver/parallel/domain.hpp"
#include "solver/parallel/mesh_part.hpp"
#include "solver/time_function.hpp"

namespace tribex::solver {

/// Kinematic constraints: each constrained dof once, with its kind.
struct Constraints {
  enum class Kind : unsigned char { fixed, displacement, velocity };
  std::vector<int> dof;                 // 3 * node + component
  std::vector<Kind> kind;
  std::vector<int> function;            // index into Model::functions (-1 for fixed)
  std::vector<double> scale;
};

/// Follower pressure on side-set faces: f_I = -p(t) a_f / 4 on each face node, a_f the face's
/// current area vector (outward), p > 0 pushing into the body.
struct PressureLoad {
  std::vector<int> face_nodes;  // [face][4]
  std::vector<int> face_element;  // [face] the element the face belongs to (partitioning)
  int function = -1;
  double scale = 1.0;           // Pa per function unit
};

/// Prescribed total force on a node set (`begin prescribed force`): each listed dof gets
/// scale * function(t), the total divided by the node count.
struct NodalForceLoad {
  std::vector<int> dof;     // 3 * node + component
  int function = -1;
  double scale = 1.0;       // N per function unit, per node
};

/// Lysmer-Kuhlemeyer dashpots lumped to nodes (docs/theory.md 4.2): per node an area-weighted unit
/// normal and the coefficients c_n = a rho c_p A_I, c_t = b rho c_s A_I (N s/m).
struct SilentBoundaryNodes {
  std::vector<int> node;
  std::vector<double> normal;   // [k][3]
  std::vector<double> c_normal;
  std::vector<double> c_tangential;
};

struct Model {
  mesh::Mesh mesh;
  std::vector<ElementBlock> blocks;
  std::vector<double> mass;            // [node] lumped mass, kg (row sum, rho V0 / 8 per element)
  std::vector<double> initial_velocity;  // [node][3]
  std::vector<TimeFunction> functions;
  std::vector<std::string> function_names;
  Constraints constraints;
  std::vector<PressureLoad> pressures;
  std::vector<NodalForceLoad> nodal_forces;
  SilentBoundaryNodes silent;
  RigidBodies rigid_bodies;            // `begin rigid body`: nodes moving as one rigid body (translating, or turning)
  double mass_damping = 0.0;           // 1/s
  /// [node] kg: the mass the mass damping force -c m v acts with, the unscaled lumped mass when mass
  /// scaling is active and the region is damped (docs/theory.md 1.4.1); empty: Model::mass.
  std::vector<double> damping_mass;
  double total_mass = 0.0;             // kg, unscaled (rho V0 summed); Model::mass includes mass scaling
  MassScalingReport mass_scaling;      // `begin mass scaling`: what set-up added (inactive without the block)
  std::vector<int> element_block;      // [element] index into blocks
  /// [block] the block whose body it belongs to: itself, or for a `surface layer block` the block it was
  /// split from (so the guards see a tip and its skin as one body, solver/guards/block_translation.hpp).
  std::vector<int> block_body;
  /// Contact, when the region has a contact definition (set up by build_model).
  std::unique_ptr<contact::ContactManager> contact;
  /// [surface node] the whole mesh's node of each node in the contact's numbering (contact_setup.hpp).
  std::vector<int> contact_global_node;
  /// [surface node][3] the reference positions of the contact's nodes, m (a distributed run's ghost
  /// rows start from them, solver/parallel/contact_region.hpp).
  std::vector<double> contact_reference;
  std::vector<std::string> preflight;  // lines for the pre-flight report (initial contact gaps, ...)
  SetupFindings setup;  // warnings and unsafe choices found at set-up, for the run guards (solver/guards/README.md)
  /// This rank's share of a parallel run (from its MeshPart); identity on one rank.
  parallel::Domain domain;
};

/// Build the mesh named by the region and everything above from a parsed deck. Throws SetupError
/// (deck line + what is missing) when the deck and the mesh disagree, mesh::MeshError for a bad
/// mesh file.
Model build_model(const inputs::Deck& deck);

/// The same on a mesh built elsewhere (tests, tools that generate meshes themselves).
Model build_model(const inputs::Deck& deck, mesh::Mesh mesh);

/// Collective, in a parallel run: this rank's model from its part of the mesh alone
/// (parallel::distribute_mesh). Nodal values that sum over elements (lumped mass, added mass,
/// silent-boundary coefficients) are summed over the ranks that share a node; `contact_faces` are
/// those of the whole mesh (contact_faces on rank 0, broadcast; ignored without contact). An error
/// found on some ranks only stops every rank with the lowest one's message.
Model build_model(const inputs::Deck& deck, parallel::MeshPart part, const ContactFaces& contact_faces);

/// The P-wave modulus lambda + 2 mu (Pa) of each block of `mesh` (the deck region's mesh, as
/// build_mesh builds it), from the material its parameters name: the values build_model's blocks get,
/// for a stage that runs before it (the partition). 0 for a block the deck gives no parameters for
/// (build_model reports that).
std::vector<double> block_wave_moduli(const inputs::Deck& deck, const mesh::Mesh& mesh);

/// The mesh of the deck's region (its finite element model), as build_model(deck) builds it.
mesh::Mesh build_mesh(const inputs::Deck& deck);

/// The mesh of a finite element model spec: generated boxes (appended in deck order) or a gmsh file.
mesh::Mesh build_mesh(const inputs::FiniteElementModelSpec& spec);
/// The plan of the deck's generated mesh (mesh/generated_plan.hpp: build_mesh(deck)'s numbers,
/// coordinates and sets, no volume built), or none with the reason in `why_not` where build_mesh
/// needs the whole mesh (a mesh file, an AFM surface, `gap above surface`, surface layer blocks, rigid
/// bodies). Throws as build_mesh does for a bad box or asperity.
std::optional<mesh::GeneratedPlan> generated_plan(const inputs::Deck& deck, std::string& why_not);
/// The Exodus II or gmsh file of the deck's mesh (`gmsh` says which) where build_mesh(deck) is that file
/// alone, so that the ranks can read it in slices (`set-up = distributed`, parallel/file_slice_source.hpp); else
/// none with the reason in `why_not` (surface layer blocks, rigid bodies; a generated mesh: none, `why_not`
/// empty).
std::optional<std::string> mesh_slices_path(const inputs::Deck& deck, std::string& why_not, bool& gmsh);

}  // namespace tribex::solver
