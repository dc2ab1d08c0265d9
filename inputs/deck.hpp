// SPDX-License-Identifier: MIT
// The typed, validated form of an input deck: what `inputs` hands to the rest of tribex.
//
// Every value here is SI (unit suffixes in the deck are converted by the parser) and every
// cross-reference between blocks (material, section, function, block names) has been checked
// by the parser. Cross-references into the mesh (node sets, side sets, block names of a mesh
// file) cannot be checked without the mesh; they carry a SourceLocation so that the layer that
// builds the mesh can report `deck.i:LINE:COL: ...` itself.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contact/laws/law_key.hpp"
#include "inputs/keys/key_decl.hpp"

namespace tribex::inputs {

/// Where a value or block came from, for error messages (`file:line:col`).
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
  std::string str() const;  // "file:line:col"
};

/// A deck parameter `{NAME = EXPRESSION}` with its value (inputs/parameters.hpp).
struct DeckParameter {
  std::string name;
  double value = 0.0;        // SI
  std::string unit;          // SI unit text of its dimension ("m", "J/m^2"); "" when dimensionless
  bool set_on_command_line = false;  // `--set NAME=...` replaced the deck's value
  SourceLocation where;      // the definition line
};

/// One `--set NAME=EXPRESSION` of the command line (inputs/parameters.hpp).
struct ParameterSetting {
  std::string name;
  std::string expression;
};

/// `begin function NAME` with `type = piecewise linear` and a `begin values` table (t, f(t)).
/// Outside the table the function is held constant at its end values.
struct FunctionSpec {
  std::string name;
  std::vector<double> abscissa;  // time, s; strictly increasing
  std::vector<double> ordinate;  // dimension fixed by its use (m for displacement, m/s for velocity, ...)
  SourceLocation where;
};

/// A material model by its deck name: one of materials::model_names() (materials/material.hpp).
using MaterialModel = std::string;

/// `begin parameters for model MODEL` inside a material. Either (E, nu) or (K, G) may be given in
/// the deck; the parser stores the pair (E, nu) with E > 0 and -1 < nu < 0.5.
struct MaterialModelParameters {
  MaterialModel model = "elastic";
  double youngs_modulus = 0.0;  // Pa
  double poissons_ratio = 0.0;  // -
  keys::KeyValues parameters;  // the model's own keys by name (materials::model_keys), SI, defaults filled in
  SourceLocation where;
};

/// `begin property specification for material NAME`.
struct MaterialSpec {
  std::string name;
  double density = 0.0;  // kg/m^3, > 0
  std::vector<MaterialModelParameters> models;
  SourceLocation where;
  SourceLocation density_where;  // the `density` line (set-up names it when rho V underflows)
};

enum class ElementFormulation { mean_quadrature, fully_integrated };

/// `begin solid section NAME`. Defaults follow docs/theory.md sections 1.5 and 2.2.
struct SectionSpec {
  std::string name;
  ElementFormulation formulation = ElementFormulation::mean_quadrature;
  double hourglass_stiffness = 0.05;      // kappa_hg, -
  double hourglass_viscosity = 0.0;       // nu_hg, -
  double linear_bulk_viscosity = 0.06;    // b1, -
  double quadratic_bulk_viscosity = 1.2;  // b2, -
  SourceLocation where;
};

/// `begin generated box NAME` inside a finite element model (our extension): a structured hex8
/// box that becomes one element block named NAME, with node sets and side sets
/// NAME_xmin, NAME_xmax, NAME_ymin, NAME_ymax, NAME_zmin, NAME_zmax.
struct GeneratedBoxSpec {
  std::string block_name;
  std::array<double, 3> origin{0.0, 0.0, 0.0};  // m
  std::array<double, 3> size{1.0, 1.0, 1.0};    // m, > 0
  std::array<int, 3> intervals{1, 1, 1};        // elements per axis, >= 1
  /// Optional geometric grading: elements shrink toward this face ("xmin" ... "zmax"), each
  /// element `grading_ratio` times the size of its neighbour nearer that face. Empty: uniform.
  std::string grade_toward;
  double grading_ratio = 1.0;  // >= 1
  SourceLocation where;
};

/// `begin generated asperity` inside a finite element model (our extension, mesh/asperity.hpp):
/// blocks `tip`, `substrate` (and `coating`); side and node sets tip_surface, tip_top, tip_sides,
/// substrate_top, substrate_bottom, substrate_sides; node sets tip_axis_top, tip_apex,
/// substrate_axis_top, substrate_axis_bottom.
struct GeneratedAsperitySpec {
  double radius = 27e-9;
  double tip_width = 20e-9;
  double tip_height = 15e-9;
  double substrate_width = 40e-9;
  double substrate_depth = 20e-9;
  double gap = 0.0;
  double element_size = 0.5e-9;
  double fine_half_width = 4e-9;
  double fine_depth = 2e-9;
  double grading_ratio = 1.25;
  double coating_thickness = 0.0;
  int coating_layers = 6;
  bool quarter = false;  // `symmetry = quarter`: x, y >= 0 only, node sets symmetry_x, symmetry_y
  bool tip_only = false;  // `substrate = none`: blocks and sets of the tip only (over an `afm surface`)
  bool paraboloid = false;  // `tip profile = paraboloid`: z = r^2/(2R) instead of the sphere
  std::optional<std::array<double, 3>> apex;  // `apex position`: where the apex goes, m (default (0, 0, gap))
  std::optional<double> gap_above_surface;    // m: tip lowered to this vertical gap over the `afm surface`
  std::optional<std::array<double, 2>> fine_x_range;  // `fine x range`: the substrate's fine strip X0 X1, m
  SourceLocation where;
  std::map<std::string, SourceLocation> key_where;  // the line of each key the deck gives (limit messages)
};

/// `begin afm surface` inside a finite element model: an all-hex substrate block whose top follows
/// an AFM height map (mesh/afm/afm_mesh.hpp; blocks `substrate` and `coating`, side sets and node
/// sets substrate_top, substrate_track, substrate_bottom, substrate_sides, substrate_xmin ... _ymax).
struct AfmSurfaceSpec {
  std::string file;  // height-map file, resolved relative to the deck's folder
  int channel = -1;  // Nanoscope channel; -1: the first height channel
  std::optional<std::array<double, 4>> window;  // x0 y0 width height, m; unset: the whole map
  std::optional<std::array<double, 4>> track;   // x0 y0 width height, m; unset: the window
  double element_size = 0.5e-9;     // m, > 0
  double depth = 50e-9;             // m, > 0
  double coating_thickness = 0.0;   // m, >= 0 (0: no coating block)
  int coating_layers = 6;           // 1 to 100
  double grading_ratio = 1.3;       // in [1, 1.3]
  bool interpolate_small_window = false;  // `small window = interpolate`
  SourceLocation where;
};

/// `begin surface layer block NAME` inside a finite element model: the elements of `from_block`
/// within `layers` element layers of `surface` become block NAME (mesh/surface_layers.hpp); applied
/// in deck order after the mesh is built or read.
struct SurfaceLayerBlockSpec {
  std::string name;
  std::string from_block;
  std::string surface;  // a side set, or a node set when there is no side set of that name
  int layers = 1;       // >= 1
  SourceLocation where, from_block_where, surface_where;  // the begin line, the two key lines
};

/// `begin parameters for block NAME` inside a finite element model.
struct BlockParameters {
  std::string block;     // must exist in the mesh (checked when the mesh is built)
  std::string material;  // checked by the parser
  MaterialModel model = "elastic";  // the material must define this model
  std::string section;   // checked by the parser
  SourceLocation where;
};

/// `begin finite element model NAME`.
struct FiniteElementModelSpec {
  std::string name;
  enum class Source { generated, gmsh, exodus } source = Source::generated;
  std::string database_path;  // gmsh, exodus: path resolved relative to the deck's folder
  std::vector<GeneratedBoxSpec> boxes;  // generated: boxes (appended in deck order)
  std::optional<GeneratedAsperitySpec> asperity;  // generated: the asperity problem
  std::optional<AfmSurfaceSpec> afm_surface;       // generated: a block from an AFM height map
  std::vector<SurfaceLayerBlockSpec> surface_layers;  // any source: blocks split off after meshing
  std::vector<BlockParameters> blocks;
  SourceLocation where;
};

/// `begin time control` inside the procedure.
struct TimeControlSpec {
  double start_time = 0.0;               // s
  double termination_time = 0.0;         // s, > start_time
  double time_step_scale_factor = 0.9;   // s_f in (0, 1]
  std::optional<double> maximum_time_step;  // s; caps the stable estimate when given
  // `viscous dissipation = exact`: the energy ledger pairs the element viscous forces F_v^n with
  // v^{n+1/2} from a per-node copy the kernels fill (docs/theory.md 1.3), at a kernel cost of 17-28 %;
  // the default (`half step`) takes that half equal to the F_v^n . v^{n-1/2} half.
  bool exact_viscous_dissipation = false;
  SourceLocation where;
};

enum class Component { x = 0, y = 1, z = 2 };

/// `begin fixed displacement`: zero displacement and velocity of the listed components.
struct FixedDisplacementSpec {
  std::string node_set;
  std::vector<Component> components;
  SourceLocation where;
};

/// `begin prescribed displacement` / `begin prescribed velocity`: u_c(t) or v_c(t) =
/// scale_factor * function(t) on every node of the node set.
struct PrescribedMotionSpec {
  enum class Kind { displacement, velocity } kind = Kind::displacement;
  std::string node_set;  // with `rigid body = NAME`: NAME, the node set build_mesh adds for the body
  Component component = Component::x;
  std::string function;  // checked by the parser
  double scale_factor = 1.0;
  SourceLocation where;
  std::string rigid_body;  // `rigid body = NAME`: drives the body's reference point (empty: a node set)
};

/// `begin initial velocity`: v(t=0) on a node set or on every node of a block.
struct InitialVelocitySpec {
  std::string node_set;  // exactly one of node_set / block is non-empty
  std::string block;
  std::array<double, 3> velocity{0.0, 0.0, 0.0};  // m/s
  SourceLocation where;
};

/// `begin pressure`: p(t) = scale_factor * function(t) on a side set, positive pushing into the
/// body (along the inward normal).
struct PressureSpec {
  std::string side_set;
  std::string function;  // checked by the parser
  double scale_factor = 1.0;  // Pa per unit of the function value
  SourceLocation where;
};

/// `begin prescribed force`: a total force F_c(t) = scale_factor * function(t) along one component
/// on a node set, shared equally by its nodes (load control, e.g. holding the normal load on a
/// tip top while another component is driven). The node set's dofs of that component must be free.
struct PrescribedForceSpec {
  std::string node_set;  // with `rigid body = NAME`: NAME, the node set build_mesh adds for the body
  Component component = Component::x;
  std::string function;       // checked by the parser
  double scale_factor = 1.0;  // N per unit of the function value
  SourceLocation where;
  std::string rigid_body;  // `rigid body = NAME`: the force acts on the body's reference point
};

/// `begin rigid body NAME` (Sierra/SM `rigid body`, Abaqus *RIGID BODY / *COUPLING kinematic, LS-DYNA
/// *CONSTRAINED_NODAL_RIGID_BODY): the nodes of a node set or a block move as one rigid body whose
/// reference point takes the boundary conditions that name it (`rigid body = NAME` in `begin prescribed
/// displacement | velocity | force`) and reports its reaction force and moment (solver/setup/rigid_bodies.hpp).
/// Rotation fixed (the default: the body translates only, or turns as a `prescribed rotation | angular
/// velocity` drives it about its reference point) or free about some global axes (docs/theory.md 1.6).
struct RigidBodySpec {
  std::string name;
  std::string node_set;  // exactly one of node_set / block is non-empty
  std::string block;
  std::optional<std::array<double, 3>> reference_point;  // m; default: the centroid of the body's nodes
  SourceLocation where;
  bool rotation_free = false;                         // `rotation = free`
  std::array<bool, 3> free_axes{true, true, true};   // `rotation axes`: the axes a free body turns about
};

/// `begin prescribed rotation` / `begin prescribed angular velocity` with `rigid body = NAME`: the angle
/// theta_c(t) (rad) or the angular velocity omega_c(t) (rad/s) of the body about the global axis c through
/// its reference point, scale_factor * function(t) (`angle unit = deg` folded into scale_factor).
struct PrescribedRotationSpec {
  enum class Kind { angle, angular_velocity } kind = Kind::angle;
  std::string rigid_body;
  Component component = Component::x;  // the axis
  std::string function;
  double scale_factor = 1.0;  // rad (or rad/s) per unit of the function value
  SourceLocation where;
};

/// `begin silent boundary`: Lysmer-Kuhlemeyer dashpots on a side set (docs/theory.md section 4).
struct SilentBoundarySpec {
  std::string side_set;
  double normal_coefficient = 1.0;      // a, -
  double tangential_coefficient = 1.0;  // b, -
  SourceLocation where;
};

/// `contact surface NAME contains SIDESET [SIDESET ...]` inside a contact definition.
struct ContactSurfaceSpec {
  std::string name;
  std::vector<std::string> side_sets;  // must exist in the mesh (checked by the solver)
  SourceLocation where;
};

/// `enforcement = node to face | mortar` (contact/README.md: when each is adequate).
enum class InteractionEnforcement { node_to_face, mortar };

/// `begin interaction NAME` inside a contact definition: `surfaces = SLAVE MASTER` (the slave
/// should be the softer surface, else the finer; solver/setup/contact_setup.cpp swaps a one-pass node-to-face
/// pair whose slave is more than twice as stiff as its master), `model = LAW` (a contact law of the list
/// in contact/laws/contact_law.hpp, with the keys it declares), `symmetric = on|off` (two-pass).
struct InteractionSpec {
  std::string name;
  std::string slave;   // surface names, checked by the parser
  std::string master;
  std::string model = "frictionless";  // a law's deck name, checked by the builder
  bool symmetric = false;
  InteractionEnforcement enforcement = InteractionEnforcement::node_to_face;
  /// `force direction = axis`: the penalty force along the contact axis instead of the master normal (the
  /// small-slope contact of the half-space theories; contact/README.md "Force direction").
  bool force_along_axis = false;
  contact::KeyValues values;           // the law's keys the deck gives (SI; paths resolved against the deck)
  std::map<std::string, SourceLocation> key_where;  // where each of them is given
  SourceLocation where;
  /// Where key `key` is given, else the interaction's line.
  const SourceLocation& where_of(const std::string& key) const {
    const auto it = key_where.find(key);
    return it == key_where.end() ? where : it->second;
  }
};

/// `begin contact definition NAME` inside the region (docs/theory.md 5; docs/conventions.md contact).
struct ContactSpec {
  std::string name;
  std::vector<ContactSurfaceSpec> surfaces;
  std::vector<InteractionSpec> interactions;
  double penalty_scale_factor = 1.0;        // k_p dt^2 / m_eff, (0, 2]
  std::optional<double> search_margin;      // m; default: mean face edge of the master surface
  /// `contact axis = px py pz dx dy dz` (point and direction) from which the contact radii are measured (contact_radius, _edge, _max, _pressure_fit).
  std::optional<std::array<double, 6>> axis;
  /// Largest initial overlap accepted before the run (m); default 0.01 x the mean face edge.
  std::optional<double> initial_overlap_tolerance;
  SourceLocation where;
};

/// `begin results output NAME`: results.h5 + results.xdmf in the output folder.
struct ResultsOutputSpec {
  std::optional<double> time_increment;  // s; exactly one of the two increments is set
  std::optional<int> step_increment;
  std::vector<std::string> nodal_variables;    // rows of inputs/result_fields.hpp (nodal), deck order
  std::vector<std::string> element_variables;  // rows of inputs/result_fields.hpp (element), deck order
  bool xdmf = true;     // `format`: xdmf (default) or both -> results.h5 + results.xdmf
  bool exodus = false;  //           exodus or both -> results.exo
  std::string length_unit = "auto";            // auto nm um m: coordinates and length fields in results.h5/.exo
  SourceLocation where;
};

/// `begin history output NAME`: rows of history.csv. Extra columns per listed node set:
/// `<set>_reaction_{x,y,z}` (sum of the constraint reactions) and `<set>_displacement_{x,y,z}`
/// (mean displacement).
struct HistoryOutputSpec {
  std::optional<double> time_increment;  // s; exactly one of the two increments is set
  std::optional<int> step_increment;
  std::vector<std::string> reaction_force_node_sets;
  std::vector<std::string> displacement_node_sets;
  SourceLocation reaction_force_where, displacement_where;  // the key lines (set-up checks the node sets)
  SourceLocation where;
};

/// `begin restart output [NAME]`: restart files in the output folder, written every `step increment`
/// steps and/or every `wall time increment` seconds of wall-clock time (at least one of the two),
/// into a ring of `ring size` files restart_0.h5, restart_1.h5, ...; restart.h5 is always the newest.
struct RestartOutputSpec {
  std::optional<int> step_increment;
  std::optional<double> wall_time_increment;  // s of wall-clock time
  int ring_size = 2;
  SourceLocation where;
};

/// The run guards' thresholds (keys of `begin presto region`; solver/guards/README.md): each
/// warning is reported once, at its first crossing, with its maximum at the end; a limit stops the run
/// (exit 3).
struct GuardSpec {
  double energy_error_warning = 0.01;        // relative energy balance error
  std::optional<double> energy_error_limit;  // stop when the relative error exceeds it
  double penetration_warning = 0.2;          // contact penetration / local element size sqrt(A_I)
  bool quasi_static = false;                 // the deck declares the run quasi-static
  double kinetic_energy_warning = 0.05;      // kinetic / internal energy bound of a quasi-static run
  double contact_motion_warning = 0.5;       // one-step surface motion / contact capture distance
  double contact_motion_limit = 1.0;         // the same, stop (tunnelling)
  // Mass-scaled quasi-static runs (`begin mass scaling`, `maximum kinetic energy ratio`): kinetic less
  // the blocks' mean translation over internal energy, while loaded, that stops the run (exit 3).
  std::optional<double> kinetic_energy_limit;
};

/// `begin mass scaling` (solver/setup/mass_scaling.hpp, docs/theory.md 1.4.1): selective mass scaling. Every
/// element of the listed blocks whose stable step is below the element target gets its density raised
/// by (dt_target / dt_e)^2 so that its step equals the target. Exactly one of `target time step`
/// (the run's time step, s) and `largest factor` (target = factor x the run's unscaled step) is set.
struct MassScalingSpec {
  std::optional<double> target_time_step;  // s, the run's step (after the time step scale factor)
  std::optional<double> largest_factor;    // >= 1
  std::vector<std::string> blocks;         // empty: every block
  double maximum_added_mass_fraction = 0.05;  // added / unscaled total mass; exit 3 above it
  std::optional<double> maximum_kinetic_energy_ratio;  // quasi static: KE / IE limit (exit 3); 0.1 by default there
  SourceLocation target_where, blocks_where, where;
};

/// `begin decomposition` (solver/parallel/partition.hpp): how a parallel run splits the model. `auto` (the
/// default) is `ptscotch` with `set-up = distributed` for a mesh of `distributed above` elements or more
/// (when its source allows it) and `metis` otherwise; `metis` partitions the element graph on rank 0,
/// `ptscotch` the same graph on all the ranks together (solver/parallel/ptscotch_partition.hpp), `rcb`
/// bisects the element centroids; `coordinate scale` multiplies the coordinates when the sides of a
/// box are compared (the volume's with rcb, the contact patches' with either method), so a small
/// factor on the direction a contact zone travels keeps it shared by the ranks. Not given: the run
/// takes 0.01 on the direction the deck moves a contact body along (solver/parallel/contact_travel.hpp).
struct DecompositionSpec {
  enum class Method { automatic, metis, rcb, ptscotch };
  Method method = Method::automatic;
  int distributed_above = 500000;  // method = auto: the element count from which the set-up is distributed
  std::optional<std::array<double, 3>> coordinate_scale;  // the deck's; empty: from the contact's travel
  bool distributed_setup = false;  // `set-up = distributed`: each rank generates its slab (ptscotch only)
  SourceLocation where;
};

/// `begin presto region NAME`.
struct RegionSpec {
  std::string name;
  std::string finite_element_model;  // `use finite element model NAME`, checked by the parser
  std::vector<FixedDisplacementSpec> fixed_displacements;
  std::vector<PrescribedMotionSpec> prescribed_motions;
  std::vector<InitialVelocitySpec> initial_velocities;
  std::vector<PressureSpec> pressures;
  std::vector<PrescribedForceSpec> prescribed_forces;
  std::vector<RigidBodySpec> rigid_bodies;
  std::vector<PrescribedRotationSpec> prescribed_rotations;
  std::vector<SilentBoundarySpec> silent_boundaries;
  double mass_damping_coefficient = 0.0;  // 1/s: f_damp = -c m v (`mass damping coefficient`)
  GuardSpec guards;
  std::optional<MassScalingSpec> mass_scaling;
  DecompositionSpec decomposition;  // defaults without the block
  std::optional<ContactSpec> contact;
  std::optional<ResultsOutputSpec> results;
  std::optional<HistoryOutputSpec> history;
  std::optional<RestartOutputSpec> restart;
  SourceLocation where;
};

/// `begin presto procedure NAME`.
struct ProcedureSpec {
  std::string name;
  TimeControlSpec time_control;
  RegionSpec region;
  SourceLocation where;
};

/// The whole deck: `begin sierra NAME ... end sierra`.
struct Deck {
  std::string name;
  std::string path;  // the deck file as given
  std::vector<std::string> files_read;  // the deck and every file it includes, as opened (a run never writes them)
  std::vector<FunctionSpec> functions;
  std::vector<MaterialSpec> materials;
  std::vector<SectionSpec> sections;
  std::vector<FiniteElementModelSpec> models;
  ProcedureSpec procedure;
  /// The resolved deck, defaults filled in, in deck syntax: echoed to log.txt.
  std::string resolved_text;
  /// `{NAME = ...}` parameters in definition order, with --set values applied (summary.json "parameters").
  std::vector<DeckParameter> parameters;

  const FunctionSpec* find_function(const std::string& n) const;
  const MaterialSpec* find_material(const std::string& n) const;
  const SectionSpec* find_section(const std::string& n) const;
  const FiniteElementModelSpec* find_model(const std::string& n) const;
};

}  // namespace tribex::inputs
