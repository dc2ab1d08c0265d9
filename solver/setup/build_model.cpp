// SPDX-License-Identifier: MIT
#include "solver/model.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <map>

#include "inputs/did_you_mean.hpp"
#include "mesh/asperity.hpp"
#include "mesh/asperity_limits.hpp"
#include "mesh/box.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/vertical_gap.hpp"
#include "solver/setup/afm_surface_mesh.hpp"
#include "solver/setup/contact_setup.hpp"
#include "solver/errors.hpp"
#include "solver/output/run_log.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/stable_time_step.hpp"
#include "solver/setup/surface_layer_blocks.hpp"

namespace tribex::solver {
namespace {

template <class Map>
std::vector<std::string> keys_of(const Map& m) {
  std::vector<std::string> k;
  for (const auto& [name, value] : m) k.push_back(name);
  return k;
}

std::string list_names(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < 12; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > 12) s += ", ...";
  return s.empty() ? "none" : s;
}

[[noreturn]] void missing(const inputs::SourceLocation& where, const std::string& what, const std::string& name,
                          const std::vector<std::string>& known) {
  const std::string hint = inputs::closest_match(name, known);
  throw SetupError(where.str() + ": error: " + what + " '" + name + "' is not in the mesh" +
                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)") + "; the mesh has: " + list_names(known));
}

int function_index(const Model& model, const std::string& name) {
  auto it = std::find(model.function_names.begin(), model.function_names.end(), name);
  return static_cast<int>(it - model.function_names.begin());  // existence checked by the parser
}

// The deck's parameters for the mesh block `name` (null where the deck has none).
const inputs::BlockParameters* parameters_of(const inputs::FiniteElementModelSpec& fem, const std::string& name) {
  const auto p = std::find_if(fem.blocks.begin(), fem.blocks.end(), [&](const auto& q) { return q.block == name; });
  return p == fem.blocks.end() ? nullptr : &*p;
}

// A density whose element masses rho V0 / 8 underflow to 0 (issue 54, item 16: 1e-300 kg/m^3 on nm
// elements): named at the deck's density line, not as a node of no element.
SetupError underflowing_density(const inputs::FiniteElementModelSpec& fem, const inputs::Deck& deck,
                                const std::string& block, double rho, double volume) {
  const auto* p = parameters_of(fem, block);
  const auto* material = p ? deck.find_material(p->material) : nullptr;
  char b[200];
  std::snprintf(b, sizeof b, "density %g kg/m^3 gives the elements of block '%s' (volume %g m^3) a mass of 0 kg "
                "(rho V underflows double precision); give the material's physical density", rho, block.c_str(), volume);
  return SetupError((material ? material->density_where.str() + ": error: " : std::string()) + b);
}

materials::Material make_material(const inputs::MaterialSpec& spec, inputs::MaterialModel model) {
  for (const auto& p : spec.models)
    if (p.model == model)
      return materials::make_material(materials::model_index(model), p.youngs_modulus, p.poissons_ratio, spec.density,
                                      p.parameters);
  throw SetupError(spec.where.str() + ": error: material '" + spec.name + "' has no parameters for the model used");
}

// Quad area vector (outward for the counter-clockwise node order): half the cross product of the
// diagonals, exact for a planar quad and the mean normal of a warped one.
void area_vector(const double* x, const std::array<int, 4>& n, double a[3]) {
  double d1[3], d2[3];
  for (int i = 0; i < 3; ++i) {
    d1[i] = x[3 * n[2] + i] - x[3 * n[0] + i];
    d2[i] = x[3 * n[3] + i] - x[3 * n[1] + i];
  }
  a[0] = 0.5 * (d1[1] * d2[2] - d1[2] * d2[1]);
  a[1] = 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]);
  a[2] = 0.5 * (d1[0] * d2[1] - d1[1] * d2[0]);
}

// `gap above surface`: the tip (nodes from first_tip_node on) moves vertically so that its bottom face
// (tip_surface) is `gap` above the AFM surface's top (substrate_top) at the closest point, measured
// vertically (mesh/vertical_gap.hpp).
void place_tip_above_surface(mesh::Mesh& m, int first_tip_node, double gap) {
  const auto now = mesh::smallest_vertical_gap(m, "tip_surface", "substrate_top");
  if (!now)
    throw mesh::MeshError("'gap above surface': the tip's footprint lies outside the AFM surface's window; move "
                          "'apex position' x y over the window (or enlarge the window)");
  for (int n = first_tip_node; n < m.node_count(); ++n) m.coordinates[3 * static_cast<std::size_t>(n) + 2] += gap - *now;
}

// The generator's spec of a deck's `begin generated box`.
mesh::BoxSpec box_spec_of(const inputs::GeneratedBoxSpec& box) {
  mesh::BoxSpec b;
  b.name = box.block_name;
  b.origin = box.origin;
  b.size = box.size;
  b.intervals = box.intervals;
  b.grade_toward = box.grade_toward;
  b.grading_ratio = box.grading_ratio;
  return b;
}

// The generator's spec of a deck's `begin generated asperity`; SetupError with every violated size
// limit at once, each at its key's line (the block's when the key is a default).
mesh::AsperitySpec checked_asperity_spec(const inputs::GeneratedAsperitySpec& a) {
  mesh::AsperitySpec g;
  g.radius = a.radius;
  g.tip_width = a.tip_width;
  g.tip_height = a.tip_height;
  g.substrate_width = a.substrate_width;
  g.substrate_depth = a.substrate_depth;
  g.gap = a.gap;
  g.element_size = a.element_size;
  g.fine_half_width = a.fine_half_width;
  g.fine_depth = a.fine_depth;
  g.grading_ratio = a.grading_ratio;
  g.coating_thickness = a.coating_thickness;
  g.coating_layers = a.coating_layers;
  g.quarter = a.quarter;
  g.tip_only = a.tip_only;
  g.paraboloid = a.paraboloid;
  if (a.apex) {
    g.place_apex = true;
    g.apex = *a.apex;
  }
  g.fine_x_range = a.fine_x_range;
  // Every violated size limit at once, each at its key's line (the block's when the key is a default).
  if (const auto violations = mesh::asperity_limit_violations(g); !violations.empty()) {
    std::string message;
    for (const auto& v : violations) {
      const auto it = a.key_where.find(v.key);
      const bool given = it != a.key_where.end();
      if (!message.empty()) message += '\n';
      message += (given ? it->second : a.where).str();
      message += ": error: asperity mesh: '";
      message += v.key;
      message += given ? "': " : "' (its default): ";
      message += v.message;
    }
    throw SetupError(message);
  }
  return g;
}

}  // namespace

mesh::Mesh build_mesh(const inputs::FiniteElementModelSpec& spec) {
  mesh::Mesh m;
  if (spec.source == inputs::FiniteElementModelSpec::Source::gmsh) {
    m = mesh::read_gmsh(spec.database_path);
  } else if (spec.source == inputs::FiniteElementModelSpec::Source::exodus) {
    m = mesh::read_exodus(spec.database_path);
  } else {
    if (spec.afm_surface) m = build_afm_surface_mesh(*spec.afm_surface);
    std::vector<mesh::BoxSpec> boxes;
    long long nodes = m.node_count(), elements = m.element_count();
    for (const auto& box : spec.boxes) {
      const mesh::BoxSpec& b = boxes.emplace_back(box_spec_of(box));
      const auto [box_nodes, box_elements] = mesh::box_size(b);
      nodes += box_nodes;
      elements += box_elements;
    }
    // The boxes written in place into room reserved for all of them: a large mesh is never copied
    // (rank 0's peak memory in a parallel set-up, docs/measurements/2026-11-26-bench-rank-counts.md
    // "Rank 0's set-up, contact patches, positions-only ghost rows").
    if (!boxes.empty() && nodes < std::numeric_limits<int>::max() / 3 && elements < std::numeric_limits<int>::max() / 8) {
      m.coordinates.reserve(static_cast<std::size_t>(3 * nodes));
      m.connectivity.reserve(static_cast<std::size_t>(8 * elements));
    }
    for (const auto& b : boxes) mesh::add_box(m, b);
    if (spec.asperity) {
      const auto& a = *spec.asperity;
      const mesh::AsperitySpec g = checked_asperity_spec(a);
      try {
        const int first_tip_node = m.node_count();
        mesh::append(m, mesh::generate_asperity(g));
        if (a.gap_above_surface) place_tip_above_surface(m, first_tip_node, *a.gap_above_surface);
      } catch (const mesh::MeshError& e) {
        const bool clash = spec.afm_surface && !a.tip_only;  // both would make block `substrate`
        throw SetupError(a.where.str() + ": error: " + e.what() +
                         (clash ? " (over an 'afm surface' the asperity needs 'substrate = none')" : ""));
      }
    }
    mesh::validate(m, "generated mesh of finite element model '" + spec.name + "'");
  }
  apply_surface_layer_blocks(m, spec);  // mixed blocks: a skin split off a block, any mesh source
  return m;
}

namespace {
const inputs::FiniteElementModelSpec& model_spec(const inputs::Deck& deck) {
  const auto& region = deck.procedure.region;
  const inputs::FiniteElementModelSpec* fem = deck.find_model(region.finite_element_model);
  if (!fem) throw SetupError(region.where.str() + ": error: unknown finite element model '" + region.finite_element_model + "'");
  return *fem;
}
}  // namespace

mesh::Mesh build_mesh(const inputs::Deck& deck) {
  mesh::Mesh mesh = build_mesh(model_spec(deck));
  add_rigid_body_node_sets(mesh, deck.procedure.region.rigid_bodies);  // node set NAME per `begin rigid body NAME`
  return mesh;
}

std::optional<mesh::GeneratedPlan> generated_plan(const inputs::Deck& deck, std::string& why_not) {
  const inputs::FiniteElementModelSpec& spec = model_spec(deck);
  // What build_mesh does beyond the boxes and the asperity needs the whole mesh (a height map's
  // spline surface, a gap measured over it, surface layers counted down a block, a rigid body's nodes).
  why_not.clear();
  if (spec.source != inputs::FiniteElementModelSpec::Source::generated) why_not = "the mesh is read from a file";
  else if (spec.afm_surface) why_not = "an AFM surface is generated on one rank";
  else if (spec.asperity && spec.asperity->gap_above_surface) why_not = "'gap above surface' measures the whole mesh";
  else if (!spec.surface_layers.empty()) why_not = "surface layer blocks are split off the whole mesh";
  else if (!deck.procedure.region.rigid_bodies.empty()) why_not = "rigid bodies collect their nodes from the whole mesh";
  if (!why_not.empty()) return std::nullopt;
  mesh::GeneratedPlan plan;
  for (const auto& box : spec.boxes) mesh::append_plan(plan, mesh::plan_box(box_spec_of(box)));
  if (spec.asperity) {
    const mesh::AsperitySpec g = checked_asperity_spec(*spec.asperity);
    try {
      mesh::append_plan(plan, mesh::plan_asperity(g));
    } catch (const mesh::MeshError& e) {
      throw SetupError(spec.asperity->where.str() + ": error: " + e.what());
    }
  }
  return plan;
}

std::optional<std::string> mesh_slices_path(const inputs::Deck& deck, std::string& why_not, bool& gmsh) {
  const inputs::FiniteElementModelSpec& spec = model_spec(deck);
  // What build_mesh adds to the file's mesh needs the whole mesh (as for generated_plan).
  why_not.clear();
  gmsh = spec.source == inputs::FiniteElementModelSpec::Source::gmsh;
  if (!gmsh && spec.source != inputs::FiniteElementModelSpec::Source::exodus) return std::nullopt;  // generated_plan's case
  if (!spec.surface_layers.empty()) why_not = "surface layer blocks are split off the whole mesh";
  else if (!deck.procedure.region.rigid_bodies.empty()) why_not = "rigid bodies collect their nodes from the whole mesh";
  if (!why_not.empty()) return std::nullopt;
  return spec.database_path;
}

std::vector<double> block_wave_moduli(const inputs::Deck& deck, const mesh::Mesh& mesh) {
  const inputs::FiniteElementModelSpec& fem = model_spec(deck);
  std::vector<double> modulus;
  for (const auto& b : mesh.blocks) {
    const auto* p = parameters_of(fem, b.name);
    const auto* material = p ? deck.find_material(p->material) : nullptr;
    const bool has_model = material && std::any_of(material->models.begin(), material->models.end(),
                                                   [&](const auto& m) { return m.model == p->model; });
    modulus.push_back(has_model ? materials::wave_modulus_of(make_material(*material, p->model)) : 0.0);
  }
  return modulus;
}

Model build_model(const inputs::Deck& deck) { return build_model(deck, build_mesh(deck)); }

namespace {

// Sizes of the whole mesh's node and side sets (a rank's part may hold none of a set's entries).
struct SetSizes {
  std::map<std::string, int> node, side;
};

SetSizes set_sizes_of(const mesh::Mesh& m) {
  SetSizes s;
  for (const auto& [name, nodes] : m.node_sets) s.node[name] = static_cast<int>(nodes.size());
  for (const auto& [name, sides] : m.side_sets) s.side[name] = static_cast<int>(sides.size());
  return s;
}

// [node] 1 where all three velocity components are prescribed (fixed or driven), for the tangential pairs.
std::vector<char> prescribed_nodes(const Model& model) {
  std::vector<char> constrained(model.mass.size(), 0), prescribed(model.mass.size(), 0);
  for (int dof : model.constraints.dof) ++constrained[static_cast<std::size_t>(dof / 3)];
  for (std::size_t n = 0; n < constrained.size(); ++n) prescribed[n] = constrained[n] == 3;
  return prescribed;
}

// The surface nodes' masses and prescribed flags in the contact's numbering (ContactGeometry): every
// rank puts in the values of the surface nodes it owns, one sum over the ranks completes them (each
// value has one owner, so the sum is exact; on one rank a copy).
struct SurfaceValues {
  std::vector<double> mass, unscaled_mass;
  std::vector<char> prescribed;
};

SurfaceValues surface_values(const Model& model, const ContactFaces& faces, const std::vector<double>& unscaled_mass) {
  const auto& d = model.domain;
  const std::vector<char> prescribed = prescribed_nodes(model);
  const std::size_t ns = faces.global_node.size();
  std::vector<double> values(3 * ns, 0.0);  // mass, unscaled mass, prescribed
  for (std::size_t k = 0; k < ns; ++k) {
    const int local = d.local_node(faces.global_node[k]);
    if (local < 0) continue;
    const auto l = static_cast<std::size_t>(local);
    if (!(d.owned[l] > 0.0)) continue;
    values[3 * k] = model.mass[l];
    values[3 * k + 1] = unscaled_mass.empty() ? 0.0 : unscaled_mass[l];
    values[3 * k + 2] = prescribed[l];
  }
  parallel::sum(values.data(), static_cast<int>(values.size()));
  SurfaceValues v;
  v.mass.resize(ns);
  v.prescribed.resize(ns);
  if (!unscaled_mass.empty()) v.unscaled_mass.resize(ns);
  for (std::size_t k = 0; k < ns; ++k) {
    v.mass[k] = values[3 * k];
    if (!unscaled_mass.empty()) v.unscaled_mass[k] = values[3 * k + 1];
    v.prescribed[k] = values[3 * k + 2] > 0.5;
  }
  return v;
}

// The contact surface nodes of a mass-scaled run raised to (dt / dt_0)^2 times their unscaled mass
// (solver/setup/mass_scaling.hpp raise_contact_node_masses; docs/theory.md 1.4.1), counted in the report over
// the ranks. `mass` and `unscaled_mass` are summed over the ranks already, so every copy of a shared node
// gets the same value.
void raise_contact_masses(Model& model, const ContactFaces& faces, const std::vector<double>& unscaled_mass, double dt) {
  const auto& d = model.domain;
  std::vector<int> nodes;
  for (int g : faces.global_node)
    if (const int l = d.local_node(g); l >= 0) nodes.push_back(l);
  MassScalingReport& r = model.mass_scaling;
  const double ratio = dt / r.unscaled_time_step;
  r.contact_mass_factor = ratio * ratio;
  const ContactMassRaise raised = raise_contact_node_masses(nodes, unscaled_mass, r.contact_mass_factor, d.owned, model.mass);
  double sums[2] = {raised.added_mass, double(raised.nodes)};
  parallel::sum(sums, 2);
  r.contact_added_mass = sums[0];
  r.contact_nodes = static_cast<int>(std::lround(sums[1]));
  r.added_mass += r.contact_added_mass;
}

// Silent boundaries, accumulated per node over the faces (the rank's faces; summed over the ranks later).
struct SilentSums {
  std::vector<double> area;          // [node][3] area vector / 4
  std::vector<double> coefficients;  // [node][3] c_n, c_t, faces touching the node
};

Model assemble(const inputs::Deck& deck, mesh::Mesh mesh, const parallel::MeshPart* part, const ContactFaces* faces);

}  // namespace

Model build_model(const inputs::Deck& deck, mesh::Mesh mesh) {
  add_rigid_body_node_sets(mesh, deck.procedure.region.rigid_bodies);  // a mesh built elsewhere (tests, tools)
  return assemble(deck, std::move(mesh), nullptr, nullptr);
}

Model build_model(const inputs::Deck& deck, parallel::MeshPart part, const ContactFaces& contact_faces) {
  mesh::Mesh mesh = std::move(part.mesh);
  return assemble(deck, std::move(mesh), &part, &contact_faces);
}

namespace {

// The set-up's state while a Model is assembled: the deck, the mesh sets' whole sizes, and the checks
// every step shares. Each member function is one step of `assemble`, in the order it calls them.
struct Assembly {
  const inputs::Deck& deck;
  const inputs::RegionSpec& region;
  const inputs::FiniteElementModelSpec& fem;
  const parallel::MeshPart* part;
  Model& model;
  const mesh::Mesh& m;
  SetSizes sizes;
  std::vector<std::string> block_names;
  struct DofOwner {
    std::string where;  // the deck location that constrained the dof
    Constraints::Kind kind;
  };
  std::map<int, DofOwner> owner;  // constrained dof -> its constraint
  SilentSums silent;

  // Node numbers in messages are the whole mesh's.
  std::string number(int local_node) const { return std::to_string(model.domain.global_node[local_node] + 1); }

  const std::vector<int>& checked_node_set(const std::string& name, const inputs::SourceLocation& where) const {
    auto it = m.node_sets.find(name);
    if (it == m.node_sets.end()) missing(where, "node set", name, keys_of(m.node_sets));
    if (sizes.node.at(name) == 0) throw SetupError(where.str() + ": error: node set '" + name + "' is empty");
    return it->second;
  }

  const std::vector<mesh::Side>& checked_side_set(const std::string& name, const inputs::SourceLocation& where) const {
    auto it = m.side_sets.find(name);
    if (it == m.side_sets.end()) missing(where, "side set", name, keys_of(m.side_sets));
    if (sizes.side.at(name) == 0) throw SetupError(where.str() + ": error: side set '" + name + "' is empty");
    return it->second;
  }

  void add_functions() {
    for (const auto& f : deck.functions) {
      model.functions.emplace_back(f);
      model.function_names.push_back(f.name);
    }
  }

  // Element blocks: every mesh block needs parameters, every parameter block a mesh block.
  void add_blocks() {
    for (const auto& b : m.blocks) block_names.push_back(b.name);
    for (const auto& p : fem.blocks)
      if (!m.find_block(p.block)) {
        const std::string hint = inputs::closest_match(p.block, block_names);
        throw SetupError(p.where.str() + ": error: block '" + p.block + "' is not in the mesh" +
                         (hint.empty() ? "" : " (did you mean '" + hint + "'?)") + "; the mesh has: " + list_names(block_names));
      }
    model.element_block.assign(static_cast<std::size_t>(m.element_count()), -1);
    for (const auto& b : m.blocks) {
      const auto* p = parameters_of(fem, b.name);
      if (!p)
        throw SetupError(fem.where.str() + ": error: mesh block '" + b.name +
                         "' has no 'begin parameters for block " + b.name + "' in finite element model '" + fem.name + "'");
      const auto* material = deck.find_material(p->material);
      const auto* section = deck.find_section(p->section);
      model.blocks.push_back(make_element_block(m, b, make_material(*material, p->model), *section,
                                                part ? model.domain.global_element : std::vector<int>{}));
      for (int e = 0; e < b.element_count; ++e) model.element_block[b.first_element + e] = static_cast<int>(model.blocks.size() - 1);
    }
  }

  // Bodies: a surface layer block belongs to the block it was split from (followed back to a block
  // of the mesh as built or read, which the split never empties).
  void assign_bodies() {
    for (const auto& b : model.blocks) {
      std::string root = b.name;
      for (auto sl = fem.surface_layers.rbegin(); sl != fem.surface_layers.rend(); ++sl)
        if (sl->name == root) root = sl->from_block;
      auto body = std::find_if(model.blocks.begin(), model.blocks.end(), [&](const auto& q) { return q.name == root; });
      model.block_body.push_back(body != model.blocks.end() ? static_cast<int>(body - model.blocks.begin())
                                                            : static_cast<int>(model.block_body.size()));
    }
  }

  // Lumped mass: rho V0 / 8 to each node of each element (docs/theory.md 1.2).
  void lump_masses() {
    const int nn = m.node_count();
    model.mass.assign(static_cast<std::size_t>(nn), 0.0);
    for (const auto& blk : model.blocks) {
      const double rho = materials::density_of(blk.material);
      for (int e = 0; e < blk.count; ++e) {
        const double share = rho * blk.volume0[e] / 8.0;
        if (!(share > 0.0) && blk.volume0[e] > 0.0) throw underflowing_density(fem, deck, blk.name, rho, blk.volume0[e]);
        for (int I = 0; I < 8; ++I) model.mass[m.connectivity[8 * (blk.first_element + e) + I]] += share;
        model.total_mass += 8.0 * share;
      }
    }
    for (int n = 0; n < nn; ++n)
      if (!(model.mass[n] > 0.0)) throw orphan_node_error(model.domain.global_node[n]);
  }

  // Kinematic constraints; a dof may be constrained once only, except that a fixed dof may be fixed
  // again: two zero displacements agree, and node sets that meet on a line need it (a quarter model's
  // symmetry plane x = 0 crosses the fixed bottom and the tip top held in x and y; verification/hertz).
  // Any other repeat (a driven dof fixed, or driven twice) is ambiguous and refused.
  void constrain(int dof, Constraints::Kind kind, int function, double scale, const inputs::SourceLocation& where) {
    auto [it, inserted] = owner.emplace(dof, DofOwner{where.str(), kind});
    if (!inserted && kind == Constraints::Kind::fixed && it->second.kind == Constraints::Kind::fixed) return;
    if (!inserted)
      throw SetupError(where.str() + ": error: node " + number(dof / 3) + " component " + "xyz"[dof % 3] +
                       " is already constrained at " + it->second.where +
                       "; constrain each component once (only a fixed one may be fixed again)");
    model.constraints.dof.push_back(dof);
    model.constraints.kind.push_back(kind);
    model.constraints.function.push_back(function);
    model.constraints.scale.push_back(scale);
  }

  void add_constraints() {
    for (const auto& f : region.fixed_displacements)
      for (int n : checked_node_set(f.node_set, f.where))
        for (auto c : f.components) constrain(3 * n + static_cast<int>(c), Constraints::Kind::fixed, -1, 0.0, f.where);
    for (const auto& p : region.prescribed_motions) {
      const auto kind = p.kind == inputs::PrescribedMotionSpec::Kind::displacement ? Constraints::Kind::displacement
                                                                                   : Constraints::Kind::velocity;
      for (int n : checked_node_set(p.node_set, p.where))
        constrain(3 * n + static_cast<int>(p.component), kind, function_index(model, p.function), p.scale_factor, p.where);
    }
  }

  void add_initial_velocities() {
    model.initial_velocity.assign(3 * static_cast<std::size_t>(m.node_count()), 0.0);
    for (const auto& iv : region.initial_velocities) {
      std::vector<int> nodes;
      if (!iv.node_set.empty()) {
        nodes = checked_node_set(iv.node_set, iv.where);
      } else {
        const mesh::Block* b = m.find_block(iv.block);
        if (!b) missing(iv.where, "block", iv.block, block_names);
        for (int e = b->first_element; e < b->first_element + b->element_count; ++e)
          for (int I = 0; I < 8; ++I) nodes.push_back(m.connectivity[8 * e + I]);
      }
      for (int n : nodes)
        for (int i = 0; i < 3; ++i) model.initial_velocity[3 * n + i] = iv.velocity[i];
    }
  }

  void add_pressures() {
    for (const auto& p : region.pressures) {
      PressureLoad load;
      for (const auto& s : checked_side_set(p.side_set, p.where)) {
        const auto nodes = m.side_nodes(s);
        load.face_nodes.insert(load.face_nodes.end(), nodes.begin(), nodes.end());
        load.face_element.push_back(s.element);
      }
      load.function = function_index(model, p.function);
      load.scale = p.scale_factor;
      model.pressures.push_back(std::move(load));
    }
  }

  // Prescribed forces: on free dofs only (a constrained dof's force would go into its reaction).
  void add_nodal_forces() {
    for (const auto& p : region.prescribed_forces) {
      NodalForceLoad load;
      const auto nodes = checked_node_set(p.node_set, p.where);
      for (int n : nodes) {
        const int dof = 3 * n + static_cast<int>(p.component);
        if (auto it = owner.find(dof); it != owner.end())
          throw SetupError(p.where.str() + ": error: 'begin prescribed force' loads node " + number(n) +
                           " component " + "xyz"[dof % 3] + ", which is constrained at " + it->second.where +
                           "; load a free component or remove the constraint");
        // On the owner's copy only: shared nodes' partial forces are summed over the ranks.
        if (model.domain.owned[n] > 0.0) load.dof.push_back(dof);
      }
      load.function = function_index(model, p.function);
      const int whole_set = sizes.node.at(p.node_set);
      load.scale = whole_set == 0 ? 0.0 : p.scale_factor / static_cast<double>(whole_set);
      model.nodal_forces.push_back(std::move(load));
    }
  }

  // Silent boundaries: accumulate area vectors and coefficients per node over the faces (docs/theory.md 4.2).
  void accumulate_silent_boundaries() {
    if (!region.silent_boundaries.empty()) {
      silent.area.assign(3 * static_cast<std::size_t>(m.node_count()), 0.0);
      silent.coefficients.assign(3 * static_cast<std::size_t>(m.node_count()), 0.0);
    }
    for (const auto& sb : region.silent_boundaries) {
      for (const auto& s : checked_side_set(sb.side_set, sb.where)) {
        const auto& blk = model.blocks[model.element_block[s.element]];
        const double rho = materials::density_of(blk.material);
        const double cp = std::sqrt(materials::wave_modulus_of(blk.material) / rho);
        const double cs = std::sqrt(materials::shear_modulus_of(blk.material) / rho);
        const auto nodes = m.side_nodes(s);
        double a[3];
        area_vector(m.coordinates.data(), nodes, a);
        const double area = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (int n : nodes) {
          for (int i = 0; i < 3; ++i) silent.area[3 * n + i] += a[i] / 4.0;
          silent.coefficients[3 * n] += sb.normal_coefficient * rho * cp * area / 4.0;
          silent.coefficients[3 * n + 1] += sb.tangential_coefficient * rho * cs * area / 4.0;
          silent.coefficients[3 * n + 2] += 1.0;
        }
      }
    }
  }

  // History columns of node sets: checked here so that `tribex check` finds a missing one.
  void check_history_sets() const {
    if (!region.history) return;
    for (const auto& name : region.history->reaction_force_node_sets) checked_node_set(name, region.history->reaction_force_where);
    for (const auto& name : region.history->displacement_node_sets) checked_node_set(name, region.history->displacement_where);
  }

  // The rank-local steps. Checks that can fail on some ranks only (a node or element of this rank's
  // part) are agreed on before the collective steps, so that every rank stops with the same message.
  void local_steps() {
    std::exception_ptr local_error;
    try {
      add_functions();
      add_blocks();
      assign_bodies();
      lump_masses();
      add_constraints();
      add_initial_velocities();
      add_pressures();
      add_nodal_forces();
      accumulate_silent_boundaries();
      model.mass_damping = region.mass_damping_coefficient;
      check_history_sets();
    } catch (...) {
      local_error = std::current_exception();
    }
    agree_on_errors(local_error);
  }

  // Mass scaling before the contact, which is built on the scaled masses and step (the junction's slip
  // prediction, the rough-surface bounds) but takes its penalty from the unscaled ones, returned here
  // (docs/theory.md 1.4.1). Both act on this rank's partial masses; the masses are summed over the
  // ranks after.
  std::vector<double> scale_and_sum_masses() {
    parallel::Domain& domain = model.domain;
    std::vector<double> unscaled_mass;
    if (region.mass_scaling) {
      const auto& tc = deck.procedure.time_control;
      if (region.contact) unscaled_mass = model.mass;
      if (model.mass_damping > 0.0) model.damping_mass = model.mass;
      model.mass_scaling = apply_mass_scaling(*region.mass_scaling, tc.time_step_scale_factor,
                                              tc.maximum_time_step.value_or(INFINITY), model);
      warn_scaled_silent_boundaries(region.silent_boundaries, model);
    }
    domain.sum_shared(model.mass.data(), 1);
    if (!unscaled_mass.empty()) domain.sum_shared(unscaled_mass.data(), 1);
    if (!model.damping_mass.empty()) {
      domain.sum_shared(model.damping_mass.data(), 1);
      if (model.mass_scaling.active)
        model.preflight.push_back("  mass damping from the unscaled masses (mass scaling): the damping force of the deck without it");
      else
        model.damping_mass.clear();
    }
    parallel::sum(&model.total_mass, 1);
    return unscaled_mass;
  }

  // The silent boundaries' per-node normals and dashpot coefficients, from the sums over the ranks.
  void finish_silent_boundaries() {
    if (silent.area.empty()) return;
    model.domain.sum_shared(silent.area.data(), 3);
    model.domain.sum_shared(silent.coefficients.data(), 3);
    for (int n = 0; n < m.node_count(); ++n) {
      if (silent.coefficients[3 * n + 2] == 0.0) continue;
      const double* acc = &silent.area[3 * static_cast<std::size_t>(n)];
      const double len = std::sqrt(acc[0] * acc[0] + acc[1] * acc[1] + acc[2] * acc[2]);
      model.silent.node.push_back(n);
      for (int i = 0; i < 3; ++i) model.silent.normal.push_back(len > 0.0 ? acc[i] / len : 0.0);
      model.silent.c_normal.push_back(silent.coefficients[3 * n]);
      model.silent.c_tangential.push_back(silent.coefficients[3 * n + 1]);
    }
  }

  // The contact on the scaled masses and step, its penalty from the unscaled ones (docs/theory.md 1.4.1).
  void add_contact(const ContactFaces* faces, std::vector<double> unscaled_mass) {
    if (!region.contact) return;
    const auto& tc = deck.procedure.time_control;
    const double dt = std::min(tc.time_step_scale_factor * whole_model_stable_time_step(model).dt,
                               tc.maximum_time_step.value_or(INFINITY));
    const ContactFaces own = faces ? ContactFaces{} : contact_faces(m, *region.contact);
    const ContactFaces& f = faces ? *faces : own;
    if (model.mass_scaling.active) raise_contact_masses(model, f, unscaled_mass, dt);
    SurfaceValues v = surface_values(model, f, unscaled_mass);
    model.contact = build_contact(*region.contact, model, {f, v.mass, std::move(v.prescribed)}, dt, &model.preflight,
                                  &model.setup);
    model.contact_global_node = f.global_node;
    model.contact_reference = f.coordinates;
    if (!model.mass_scaling.active) return;
    model.contact->set_unscaled_penalty_reference(std::move(v.unscaled_mass), model.mass_scaling.unscaled_time_step);
    model.preflight.push_back(
        format("  contact penalty from the unscaled masses and step %.6g s (mass scaling): k dt^2 / m_eff = %.3g "
               "(the penalty scale factor) on the scaled ones, as unscaled",
               model.mass_scaling.unscaled_time_step, region.contact->penalty_scale_factor));
  }
};

Model assemble(const inputs::Deck& deck, mesh::Mesh mesh, const parallel::MeshPart* part, const ContactFaces* faces) {
  Model model;
  model.mesh = std::move(mesh);
  if (part)
    model.domain.init_parallel(*part);
  else
    model.domain.init_serial(model.mesh.node_count(), model.mesh.element_count());
  Assembly a{deck, deck.procedure.region, model_spec(deck), part, model, model.mesh,
             part ? SetSizes{part->node_set_size, part->side_set_size} : set_sizes_of(model.mesh), {}, {}, {}};
  a.local_steps();
  std::vector<double> unscaled_mass = a.scale_and_sum_masses();
  a.finish_silent_boundaries();
  model.rigid_bodies = build_rigid_bodies(deck.procedure.region, model);
  for (const auto& line : describe_rigid_bodies(model.rigid_bodies)) model.preflight.push_back(line);
  a.add_contact(faces, std::move(unscaled_mass));
  // The counters report the loop's messages (summary.json rank_counts, per step): set-up's sums are not among them.
  model.domain.traffic = {};
  model.domain.communication_seconds = 0.0;
  return model;
}

}  // namespace

}  // namespace tribex::solver
