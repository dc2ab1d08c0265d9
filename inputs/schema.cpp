// SPDX-License-Identifier: MIT
#include "inputs/schema.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "inputs/declared_keys.hpp"
#include "inputs/lexer.hpp"
#include "inputs/result_fields.hpp"

namespace tribex::inputs {
namespace {

// Small constructors so that the table below reads like the deck it describes.
Range positive() { return {0.0, Range{}.hi, true, false}; }
Range non_negative() { return {0.0, Range{}.hi, false, false}; }
Range at_least(double lo) { return {lo, Range{}.hi, false, false}; }

KeySchema real(std::string name, Dimension d, Range r, bool required, std::string def, std::string help) {
  KeySchema k;
  k.name = std::move(name);
  k.kind = ValueKind::real;
  k.dimension = d;
  k.range = r;
  k.required = required;
  k.default_text = std::move(def);
  k.help = std::move(help);
  return k;
}
KeySchema reals(std::string name, Dimension d, int count, Range r, bool required, std::string def,
                std::string help) {
  KeySchema k = real(std::move(name), d, r, required, std::move(def), std::move(help));
  k.kind = ValueKind::reals;
  k.count = count;
  return k;
}
KeySchema integer(std::string name, Range r, bool required, std::string def, std::string help) {
  KeySchema k = real(std::move(name), dim::none, r, required, std::move(def), std::move(help));
  k.kind = ValueKind::integer;
  return k;
}
KeySchema integers(std::string name, int count, Range r, bool required, std::string help) {
  KeySchema k = real(std::move(name), dim::none, r, required, "", std::move(help));
  k.kind = ValueKind::integers;
  k.count = count;
  return k;
}
KeySchema text(std::string name, ValueKind kind, bool required, std::string help) {
  KeySchema k;
  k.name = std::move(name);
  k.kind = kind;
  k.required = required;
  k.help = std::move(help);
  return k;
}
KeySchema choice(std::string name, ValueKind kind, std::vector<std::string> allowed, bool required, std::string def,
                 std::string help, std::vector<std::pair<std::string, std::string>> aliases = {}) {
  KeySchema k = text(std::move(name), kind, required, std::move(help));
  k.allowed = std::move(allowed);
  k.aliases = std::move(aliases);
  k.default_text = std::move(def);
  return k;
}
KeySchema unit(std::string name, Dimension d, bool any, std::string help) {
  KeySchema k = text(std::move(name), ValueKind::unit, false, std::move(help));
  k.dimension = d;
  k.any_dimension = any;
  k.in_resolved_text = false;  // the resolved text writes the values table in SI instead
  return k;
}
KeySchema quantity(std::string name, std::string def, std::string help) {
  KeySchema k = text(std::move(name), ValueKind::quantity, false, std::move(help));
  k.default_text = std::move(def);
  return k;
}

KeySchema boolean_key(std::string name, std::string def, std::string help) {
  KeySchema k = text(std::move(name), ValueKind::boolean, false, std::move(help));
  k.default_text = std::move(def);
  return k;
}

const std::vector<std::string> components{"x", "y", "z"};
const std::vector<std::string> faces{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
// Material models and their own keys come from the one list in materials/material.hpp.
const std::vector<std::string> models = materials::model_names();
const std::vector<std::pair<std::string, std::string>> model_aliases = materials::model_aliases();

// After a block's own keys, every model's declared keys (inputs/keys/key_decl.hpp) from one list
// (declared_keys.hpp): a key several models declare appears once, its help naming them; no schema
// default, so that the resolved text of one model never carries another's key (the builder fills the
// model's defaults and rejects the keys of other models, deck_builder.cpp declared_values).
void add_declared_keys(std::vector<KeySchema>& keys, const ModelList& list) {
  const std::size_t first = keys.size();
  for (std::size_t m = 0; m < list.names.size(); ++m)
    for (const keys::KeyDecl& k : list.keys[m]) {
      const std::string key(k.key), model = list.names[m];
      auto known = std::find_if(keys.begin() + static_cast<std::ptrdiff_t>(first), keys.end(),
                                [&](const KeySchema& s) { return s.name == key; });
      if (known != keys.end()) {
        known->help.insert(known->help.size() - 1, ", " + model);  // "... (model a, b)"
        continue;
      }
      const std::string help = std::string(k.help) + " (model " + model +
                               (k.default_text.empty() ? "" : ", default " + std::string(k.default_text)) + ")";
      if (k.unit == "path") {
        keys.push_back(text(key, ValueKind::string, false, help));
        continue;
      }
      std::string unit_error;
      const auto unit = parse_unit(k.unit.empty() ? std::string_view("1") : k.unit, &unit_error);
      const Dimension d = k.unit.empty() || !unit ? dim::none : unit->dimension;
      const Range range = std::isfinite(k.lower_bound) ? Range{k.lower_bound, Range{}.hi, k.lower_open, false} : Range{};
      keys.push_back(real(key, d, range, false, "", help));
    }
}

// `begin parameters for model`: the elastic constants every model takes, then each model's own keys.
std::vector<KeySchema> material_model_keys() {
  std::vector<KeySchema> keys{
      real("youngs modulus", dim::pressure, positive(), false, "", "E (give E and nu, or K and G)"),
      real("poissons ratio", dim::none, {-1.0, 0.5, true, true}, false, "", "nu"),
      real("bulk modulus", dim::pressure, positive(), false, "", "K (give E and nu, or K and G)"),
      real("shear modulus", dim::pressure, positive(), false, "", "G")};
  add_declared_keys(keys, material_model_list());
  return keys;
}

// `begin interaction`: the pair, the law and the enforcement, then every contact law's keys.
std::vector<KeySchema> interaction_keys() {
  std::vector<KeySchema> keys{
      text("surfaces", ValueKind::strings, true,
           "SLAVE MASTER (the softer surface as slave, else the finer; node to face swaps a slave more than twice as "
           "stiff as its master, contact/README.md)"),
      choice("model", ValueKind::enumeration, contact::law_names(), false, "frictionless",
             "contact law (contact/laws/README.md; each law's keys below name it)"),
      boolean_key("symmetric", "off", "two-pass: each surface slave once, forces halved"),
      choice("enforcement", ValueKind::enumeration, {"node to face", "mortar"}, false, "node to face",
             "node to face: penalty at slave nodes; mortar: segment-to-segment (patch test, face-quadrature adhesion)"),
      choice("force direction", ValueKind::enumeration, {"normal", "axis"}, false, "normal",
             "normal: the penalty force along the master face's normal; axis: along the contact axis, the small-slope "
             "contact of the half-space theories (tractions normal to the undeformed flat; verification against them; "
             "node to face, frictionless, needs 'contact axis')")};
  add_declared_keys(keys, contact_law_list());
  return keys;
}

// Output scheduling shared by results and history output: exactly one of the two (checked by
// the builder).
std::vector<KeySchema> output_schedule() {
  return {real("time increment", dim::time, positive(), false, "",
               "write every this much simulated time; at most 1e8 output times over the run"),
          integer("step increment", at_least(1), false, "", "write every this many steps")};
}

std::vector<BlockSchema> build_table() {
  std::vector<BlockSchema> t;

  t.push_back({"sierra", NameRule::required, {}, {}, true, {},
               {{"function"},
                {"property specification for material"},
                {"solid section"},
                {"finite element model", 1},
                {"presto procedure", 1, 1}},
               false, "the whole deck"});

  t.push_back({"function", NameRule::required, {}, {}, true,
               {choice("type", ValueKind::enumeration, {"piecewise linear"}, true, "", "the kind of function"),
                unit("abscissa unit", dim::time, false, "unit of the first column (default s)"),
                unit("ordinate unit", dim::none, true,
                     "unit of the second column (default: SI of the quantity it drives)")},
               {{"values", 1, 1}},
               false, "a function of time f(t), held constant outside its table"});

  t.push_back({"values", NameRule::none, {}, {}, true, {}, {}, true,
               "rows `t f(t)`, t strictly increasing, at least 2 rows"});

  t.push_back({"property specification for material", NameRule::required, {}, {}, true,
               {real("density", dim::density, positive(), true, "", "mass density")},
               {{"parameters for model", 1}},
               false, "a material"});

  t.push_back({"parameters for model", NameRule::required, models, model_aliases, true, material_model_keys(), {},
               false, "elastic constants and parameters of one material model"});

  t.push_back({"solid section", NameRule::required, {}, {}, true,
               {choice("formulation", ValueKind::enumeration, {"mean_quadrature", "fully_integrated"}, false,
                       "mean_quadrature", "hex8 integration"),
                real("hourglass stiffness", dim::none, non_negative(), false, "0.05", "kappa_hg"),
                real("hourglass viscosity", dim::none, non_negative(), false, "0", "nu_hg"),
                real("linear bulk viscosity", dim::none, non_negative(), false, "0.06", "b1"),
                real("quadratic bulk viscosity", dim::none, non_negative(), false, "1.2", "b2")},
               {},
               false, "element formulation and artificial viscosities"});

  t.push_back({"finite element model", NameRule::required, {}, {}, true,
               {text("database name", ValueKind::string, false,
                     "mesh file, relative to the deck: gmsh .msh, or Exodus II .exo/.e/.g/.gen"),
                choice("database type", ValueKind::enumeration, {"gmsh", "exodus", "generated"}, false, "",
                       "inferred: exodus for a database name ending .exo .e .g .gen, gmsh for any other, generated without one")},
               {{"generated box"}, {"generated asperity", 0, 1}, {"afm surface", 0, 1}, {"surface layer block"},
                {"parameters for block", 1}},
               false, "the mesh and its element blocks"});

  t.push_back({"generated asperity", NameRule::none, {}, {}, true,
               {real("radius", dim::length, positive(), true, "", "R of the spherical tip"),
                choice("tip profile", ValueKind::enumeration, {"sphere", "paraboloid"}, false, "sphere",
                       "bottom face: sphere z = R - sqrt(R^2 - r^2), or Hertz's paraboloid z = r^2/(2R)"),
                real("tip width", dim::length, positive(), false, "20 nm", "side of the square tip column"),
                real("tip height", dim::length, positive(), false, "15 nm", "column height above the apex"),
                real("substrate width", dim::length, positive(), false, "40 nm", "side of the square substrate"),
                real("substrate depth", dim::length, positive(), false, "20 nm", "substrate thickness"),
                real("gap", dim::length, non_negative(), false, "0", "apex height above the substrate"),
                real("element size", dim::length, positive(), true, "", "element size at the contact"),
                real("fine half width", dim::length, positive(), false, "4 nm", "uniformly fine region |x|,|y|"),
                real("fine depth", dim::length, positive(), false, "2 nm", "uniformly fine layers in z"),
                reals("fine x range", dim::length, 2, Range{}, false, "",
                      "X0 X1: the substrate's uniformly fine region along x, X0 <= 0 <= X1 from the apex axis "
                      "(default -+fine half width): a strip as long as a slide, beyond the tip width"),
                real("grading ratio", dim::none, {1.0, 2.0, false, false}, false, "1.25", "growth per element"),
                real("coating thickness", dim::length, non_negative(), false, "0", "bonded coating (block coating)"),
                integer("coating layers", at_least(1), false, "6", "elements through the coating"),
                choice("symmetry", ValueKind::enumeration, {"none", "quarter"}, false, "none",
                       "quarter: mesh x, y >= 0 only (node sets symmetry_x, symmetry_y; forces and areas are 1/4)"),
                choice("substrate", ValueKind::enumeration, {"generated", "none"}, false, "generated",
                       "none: the tip only (block tip), e.g. above an 'afm surface' in the same model"),
                reals("apex position", dim::length, 3, Range{}, false, "",
                      "x y z of the apex (default 0 0 gap): moves the whole generated model (tip, substrate, "
                      "coating, their sets) rigidly; the substrate top is then at z - gap, centred under the apex"),
                real("gap above surface", dim::length, non_negative(), false, "",
                     "with substrate = none over an 'afm surface': lower the tip (apex x y from 'apex position', "
                     "its z not used) until its smallest vertical distance to the surface is this")},
               {},
               false, "sphere-tipped asperity above a substrate (blocks tip, substrate, coating)"});

  t.push_back({"afm surface", NameRule::none, {}, {}, true,
               {text("file", ValueKind::string, true, "AFM height map (Nanoscope, .gsf, Gwyddion matrix, xyz), relative to the deck"),
                integer("channel", {0.0, 64.0, false, false}, false, "", "Nanoscope channel (default: first height channel)"),
                reals("window", dim::length, 4, Range{}, false, "", "x0 y0 width height of the meshed part (default: whole map)"),
                reals("track", dim::length, 4, Range{}, false, "", "x0 y0 width height of the contact track (default: window)"),
                real("element size", dim::length, positive(), false, "5e-10", "largest element edge in the track"),
                real("depth", dim::length, positive(), true, "", "from the window's mean height to the flat bottom"),
                real("coating thickness", dim::length, non_negative(), false, "0", "bonded coating block on top (0: none)"),
                integer("coating layers", {1.0, 100.0, false, false}, false, "6", "elements through the coating"),
                real("grading ratio", dim::none, {1.0, 1.3, false, false}, false, "1.3",
                     "size ratio of neighbours away from the track and with depth"),
                choice("small window", ValueKind::enumeration, {"refuse", "interpolate"}, false, "refuse",
                       "a window under 4 pixels a side: an error, or the spline between the pixels meshed anyway")},
               {},
               false, "an all-hex substrate block (and coating) on an AFM height map"});

  t.push_back({"generated box", NameRule::required, {}, {}, true,
               {reals("origin", dim::length, 3, Range{}, false, "0 0 0", "lower corner"),
                reals("size", dim::length, 3, positive(), true, "", "edge lengths"),
                integers("intervals", 3, at_least(1), true, "elements per axis"),
                choice("grade toward", ValueKind::enumeration, faces, false, "",
                       "face the elements shrink toward"),
                real("grading ratio", dim::none, at_least(1.0), false, "1", "size ratio of neighbours")},
               {},
               false, "a structured hex8 box that becomes one element block"});

  // Mixed blocks (mesh/surface_layers.hpp): the element layers under a surface become a block of
  // their own, so that only they need the (slower) fully integrated section.
  t.push_back({"surface layer block", NameRule::required, {}, {}, true,
               {text("from block", ValueKind::string, true, "the block whose surface layers are split off"),
                text("surface", ValueKind::string, true, "a side set (its faces on that block) or node set"),
                integer("layers", at_least(1), true, "",
                        "element layers: 1 = elements with a node on the surface, k = those sharing a node with layer k-1")},
               {},
               false, "the element layers of a block under a surface, as a block of their own (own material and section)"});

  t.push_back({"parameters for block", NameRule::required, {}, {}, true,
               {text("material", ValueKind::string, true, "a material name"),
                choice("model", ValueKind::enumeration, models, false, "elastic", "material model",
                       model_aliases),
                text("section", ValueKind::string, true, "a solid section name")},
               {},
               false, "material and section of one element block"});

  t.push_back({"presto procedure", NameRule::required, {}, {}, true, {},
               {{"time control", 1, 1}, {"presto region", 1, 1}},
               false, "the explicit dynamics procedure"});

  t.push_back({"time control", NameRule::none, {}, {}, true,
               {real("start time", dim::time, Range{}, false, "0", "t0"),
                real("termination time", dim::time, Range{}, true, "", "end time, > start time"),
                real("time step scale factor", dim::none, {0.0, 1.0, true, false}, false, "0.9",
                     "fraction of the stable time step"),
                real("maximum time step", dim::time, positive(), false, "", "cap on the time step"),
                choice("viscous dissipation", ValueKind::enumeration, {"half step", "exact"}, false, "half step",
                       "energy ledger's pairing of the element viscous forces (exact: kernels 17-28 % slower)")},
               {},
               false, "time span and step control"});

  t.push_back({"presto region", NameRule::required, {}, {}, true,
               {text("use finite element model", ValueKind::string, true, "the model this region runs"),
                real("mass damping coefficient", dim::rate, non_negative(), false, "0", "c in f = -c m v"),
                real("energy error warning", dim::none, positive(), false, "0.01",
                     "warn when |energy balance| / largest energy exceeds it"),
                real("energy error limit", dim::none, positive(), false, "", "stop when exceeded"),
                real("penetration warning", dim::none, positive(), false, "0.2",
                     "warn when a contact penetration exceeds this fraction of the local element size"),
                boolean_key("quasi static", "off", "the run is quasi-static: watch kinetic over internal energy"),
                real("kinetic energy warning", dim::none, positive(), false, "0.05",
                     "quasi static: warn when kinetic / internal energy exceeds it while loaded"),
                real("contact motion warning", dim::none, positive(), false, "0.5",
                     "warn when surfaces move this fraction of the contact capture distance in one step"),
                real("contact motion limit", dim::none, positive(), false, "1",
                     "stop (tunnelling) when surfaces move this fraction of the capture distance in one step")},
               {{"fixed displacement"},
                {"prescribed displacement"},
                {"prescribed velocity"},
                {"initial velocity"},
                {"pressure"},
                {"prescribed force"},
                {"rigid body"},
                {"prescribed rotation"},
                {"prescribed angular velocity"},
                {"silent boundary"},
                {"contact definition", 0, 1},
                {"results output", 0, 1},
                {"history output", 0, 1},
                {"restart output", 0, 1},
                {"mass scaling", 0, 1},
                {"decomposition", 0, 1}},
               false, "boundary conditions and output"});

  t.push_back({"decomposition", NameRule::none, {}, {}, true,
               {choice("method", ValueKind::enumeration, {"auto", "metis", "rcb", "ptscotch"}, false, "auto",
                       "how a parallel run splits the elements: auto (ptscotch with set-up = distributed for a mesh of "
                       "'distributed above' elements or more, where the mesh allows it, else metis; the log says "
                       "which), metis (graph partition on rank 0, fewest shared nodes), ptscotch (the same graph "
                       "partitioned by all the ranks together with PT-Scotch; the mesh is read on rank 0 unless "
                       "set-up = distributed) or rcb (recursive coordinate bisection of the element centroids: planar cuts)"),
                integer("distributed above", at_least(1), false, "500000",
                        "with method = auto: the element count from which no rank makes the whole mesh (below it, "
                        "rank 0 makes it and METIS partitions it: at 1,009,000 elements that serial stage put rank 0 "
                        "above the per-rank memory of the others from 16 ranks on, solver/README.md)"),
                choice("set-up", ValueKind::enumeration, {"serial", "distributed"}, false, "serial",
                       "where the mesh is made: serial (rank 0 reads or generates the whole mesh and sends every rank "
                       "its part) or distributed (with method = ptscotch and a generated box or asperity or an Exodus II "
                       "file: every rank generates or reads only a slab of the elements (and of a file's nodes and sets), "
                       "the ranks partition the slabs together and exchange the elements and place the contact patches, "
                       "so that no rank holds the whole mesh: the same partition as serial with ptscotch; a mesh this "
                       "cannot make (a gmsh file, an AFM surface, gap above "
                       "surface, surface layer blocks, rigid bodies, an Exodus mesh whose contact may travel without a "
                       "coordinate scale) is set up serially, and the log says why)"),
                reals("coordinate scale", dim::none, 3, positive(), false, "",
                      "sx sy sz: coordinates multiplied by these when the sides of a box are compared (rcb's volume, "
                      "and the contact patches with either method); a small factor on the direction a contact zone "
                      "travels keeps the cuts along it, so the zone stays shared by the ranks. Default: 0.01 along "
                      "the tangential component a prescribed displacement or velocity moves a contact body farthest "
                      "over the run, where it moves farther than the smallest contact surface's extent along it over "
                      "the rank count (the run log names it), else 1 1 1")},
               {},
               false, "how a parallel run partitions the model (solver/parallel/partition.hpp)"});

  t.push_back({"mass scaling", NameRule::none, {}, {}, true,
               {real("target time step", dim::time, positive(), false, "",
                     "the run's time step (after 'time step scale factor'); elements whose step is below it get "
                     "density x (target / dt_e)^2. One of this and 'largest factor'"),
                real("largest factor", dim::none, at_least(1.0), false, "",
                     "target time step = factor x the unscaled run's time step. One of this and 'target time step'"),
                text("blocks", ValueKind::strings, false, "element blocks scaled (default: every block)"),
                real("maximum added mass fraction", dim::none, positive(), false, "0.05",
                     "stop (exit 3) when the added mass exceeds this fraction of the unscaled mass of the model"),
                real("maximum kinetic energy ratio", dim::none, positive(), false, "",
                     "quasi static runs: exit 3 when kinetic (less the blocks' mean translation) over internal energy "
                     "exceeds it while loaded (judged at the end; default 0.1 with 'quasi static = on')")},
               {},
               false, "selective mass scaling to a target time step, with its guards (docs/theory.md 1.4.1)"});

  {
    KeySchema surface = text("contact surface", ValueKind::strings, true,
                             "NAME contains SIDESET [SIDESET ...] (one line per surface)");
    surface.repeatable = true;
    t.push_back({"contact definition", NameRule::optional, {}, {}, true,
                 {surface,
                  real("penalty scale factor", dim::none, {0.0, 2.0, true, false}, false, "1",
                       "k_p dt^2 / m_eff of the penalty springs"),
                  real("search margin", dim::length, positive(), false, "",
                       "capture distance of the contact search (default: mean face edge)"),
                  reals("contact axis", dim::length, 6, Range{}, false, "",
                        "px py pz dx dy dz: point and direction of the axis the contact radii are measured from "
                        "(contact_radius, _edge, _max, _pressure_fit)"),
                  real("initial overlap tolerance", dim::length, non_negative(), false, "",
                       "largest overlap accepted at t = 0 (default: 1 % of the mean face edge)")},
                 {{"interaction", 1, unlimited}},
                 false, "contact surfaces and their interactions (docs/theory.md 5)"});
  }
  t.push_back({"interaction", NameRule::required, {}, {}, true,
               interaction_keys(),
               {},
               false, "one pair of contact surfaces and its model"});

  t.push_back({"fixed displacement", NameRule::none, {}, {}, false,
               {text("node set", ValueKind::string, true, "a node set of the mesh"),
                choice("components", ValueKind::enumerations, components, true, "", "fixed components")},
               {},
               false, "zero displacement of some components"});

  for (const char* kind : {"prescribed displacement", "prescribed velocity"}) {
    t.push_back({kind, NameRule::none, {}, {}, false,
                 {text("node set", ValueKind::string, false, "a node set of the mesh (or rigid body)"),
                  text("rigid body", ValueKind::string, false,
                       "a rigid body of the region (or node set): drives its reference point, the body translating with it"),
                  choice("component", ValueKind::enumeration, components, true, "", "driven component"),
                  text("function", ValueKind::string, true, "a function name"),
                  quantity("scale factor", "1", "multiplies the function")},
                 {},
                 false, "a component driven by a function of time"});
  }

  t.push_back({"initial velocity", NameRule::none, {}, {}, false,
               {text("node set", ValueKind::string, false, "a node set (or block)"),
                text("block", ValueKind::string, false, "an element block (or node set)"),
                reals("velocity", dim::velocity, 3, Range{}, true, "", "vx vy vz")},
               {},
               false, "velocity at t = 0"});

  t.push_back({"pressure", NameRule::none, {}, {}, false,
               {text("side set", ValueKind::string, true, "a side set of the mesh"),
                text("function", ValueKind::string, true, "a function name"),
                quantity("scale factor", "1", "Pa per unit of the function")},
               {},
               false, "p(t) on a side set, positive pushing into the body"});

  t.push_back({"prescribed force", NameRule::none, {}, {}, false,
               {text("node set", ValueKind::string, false, "a node set of the mesh (or rigid body)"),
                text("rigid body", ValueKind::string, false,
                     "a rigid body of the region (or node set): the force acts at its reference point, the body translating"),
                choice("component", ValueKind::enumeration, components, true, "", "loaded component"),
                text("function", ValueKind::string, true, "a function name (ordinate: force)"),
                quantity("scale factor", "1", "N per unit of the function")},
               {},
               false, "total force F(t) on a node set, equal shares per node (load control)"});

  t.push_back({"rigid body", NameRule::required, {}, {}, true,
               {text("node set", ValueKind::string, false, "the body's nodes: a node set of the mesh (or block)"),
                text("block", ValueKind::string, false, "the body's nodes: every node of an element block (or node set)"),
                reals("reference point", dim::length, 3, Range{}, false, "",
                      "x y z: the point the body's loads and motion refer to, its moment is taken about (default: the "
                      "centroid of its nodes)"),
                choice("rotation", ValueKind::enumeration, {"fixed", "free"}, false, "fixed",
                       "fixed: the body turns only as a prescribed rotation or angular velocity drives it; free: it "
                       "turns under the moments of the forces on it (about the axes of 'rotation axes')"),
                choice("rotation axes", ValueKind::enumerations, components, false, "x y z",
                       "with rotation = free: the global axes (through the reference point) the body turns about "
                       "freely; the others are held")},
               {},
               false, "nodes moving as one rigid body, loaded and reported at a reference point "
                      "(`rigid body = NAME` in prescribed displacement/velocity/force; solver/setup/rigid_bodies.hpp)"});

  for (const char* kind : {"prescribed rotation", "prescribed angular velocity"}) {
    const bool angle = std::string(kind) == "prescribed rotation";
    t.push_back({kind, NameRule::none, {}, {}, false,
                 {text("rigid body", ValueKind::string, true,
                       "a rigid body of the region (its rotation not free about this axis)"),
                  choice("component", ValueKind::enumeration, components, true, "",
                         "the global axis, through the body's reference point, it turns about (right-handed)"),
                  text("function", ValueKind::string, true,
                       angle ? "a function name (ordinate: the angle)" : "a function name (ordinate: the angular velocity)"),
                  quantity("scale factor", "1", angle ? "angle per unit of the function" : "angular velocity per unit of the function"),
                  choice("angle unit", ValueKind::enumeration, {"rad", "deg"}, false, "rad",
                         angle ? "the unit of the angle (function times scale factor)"
                               : "the angle's unit in the angular velocity (rad/s or deg/s)")},
                 {},
                 false, angle ? "a rigid body's rotation angle about an axis, a function of time"
                              : "a rigid body's angular velocity about an axis, a function of time"});
  }

  t.push_back({"silent boundary", NameRule::none, {}, {}, false,
               {text("side set", ValueKind::string, true, "a side set of the mesh"),
                real("normal coefficient", dim::none, non_negative(), false, "1", "a"),
                real("tangential coefficient", dim::none, non_negative(), false, "1", "b")},
               {},
               false, "absorbing dashpots"});

  {
    BlockSchema results{"results output", NameRule::required, {}, {}, true, output_schedule(), {}, false,
                        "results.h5 + results.xdmf and/or results.exo"};
    // The allowed fields are the rows of the result-field table (result_fields.hpp).
    results.keys.push_back(choice("nodal variables", ValueKind::enumerations, result_field_names(FieldKind::nodal),
                                  false, "", "nodal fields (`tribex run --list-fields`: unit and definition)"));
    results.keys.push_back(choice("element variables", ValueKind::enumerations,
                                  result_field_names(FieldKind::element), false, "",
                                  "element fields (`tribex run --list-fields`: unit and definition)"));
    results.keys.push_back(choice("format", ValueKind::enumeration, {"xdmf", "exodus", "both"}, false, "xdmf",
                                  "xdmf: results.h5 + results.xdmf; exodus: results.exo (Exodus II, with the history "
                                  "columns as global variables); both"));
    // ParaView renders noise at SI coordinates of ~1e-8 m (issue 27): the geometry and the length
    // fields are written in a unit that keeps the numbers near 1; every other field stays SI.
    results.keys.push_back(choice("length unit", ValueKind::enumeration, {"auto", "nm", "um", "m"}, false, "auto",
                                  "unit of the written coordinates and length fields (displacement, gap) in results.h5 "
                                  "and results.exo (other fields SI); auto: nm for a model under 1 um across, um under "
                                  "1 mm, else m"));
    t.push_back(results);
  }
  {
    BlockSchema history{"history output", NameRule::required, {}, {}, true, output_schedule(), {}, false,
                        "history.csv"};
    history.keys.push_back(text("reaction force", ValueKind::strings, false, "node sets"));
    history.keys.push_back(text("mean displacement", ValueKind::strings, false, "node sets"));
    t.push_back(history);
  }
  t.push_back({"restart output", NameRule::optional, {}, {}, true,
               {integer("step increment", at_least(1), false, "", "write a restart file every this many steps"),
                real("wall time increment", dim::time, positive(), false, "",
                     "write a restart file every this much wall-clock time"),
                integer("ring size", at_least(1), false, "2", "restart files kept (restart_0.h5 ...), oldest overwritten")},
               {},
               false, "restart files: the full state, for `tribex run DECK --restart OUT/restart.h5`"});
  return t;
}

}  // namespace

std::string Range::str() const {
  auto num = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return std::string(b);
  };
  const bool has_lo = lo > -std::numeric_limits<double>::infinity();
  const bool has_hi = hi < std::numeric_limits<double>::infinity();
  if (has_lo && has_hi) {
    return "in " + std::string(lo_open ? "(" : "[") + num(lo) + ", " + num(hi) + (hi_open ? ")" : "]");
  }
  if (has_lo) return (lo_open ? "> " : ">= ") + num(lo);
  if (has_hi) return (hi_open ? "< " : "<= ") + num(hi);
  return "finite";
}

const KeySchema* BlockSchema::key(std::string_view n) const {
  for (const auto& k : keys) {
    if (k.name == n) return &k;
  }
  return nullptr;
}

const ChildRule* BlockSchema::child(std::string_view n) const {
  for (const auto& c : children) {
    if (c.type == n) return &c;
  }
  return nullptr;
}

const std::vector<BlockSchema>& all_block_schemas() {
  static const std::vector<BlockSchema> table = build_table();
  return table;
}

const BlockSchema& root_schema() {
  static const BlockSchema root{"", NameRule::none, {}, {}, true, {}, {{"sierra", 1, 1}}, false, "the deck file"};
  return root;
}

const BlockSchema* find_block_schema(std::string_view type) {
  for (const auto& b : all_block_schemas()) {
    if (b.type == type) return &b;
  }
  return nullptr;
}

std::string canonical_choice(std::string_view value, const std::vector<std::string>& allowed,
                             const std::vector<std::pair<std::string, std::string>>& aliases) {
  const std::string v = lower(value);
  for (const auto& a : allowed) {
    if (a == v) return a;
  }
  for (const auto& [alias, target] : aliases) {
    if (alias == v) return target;
  }
  return "";
}

std::string join_choices(const std::vector<std::string>& allowed) {
  std::string s;
  for (std::size_t i = 0; i < allowed.size(); ++i) {
    if (i > 0) s += (i + 1 == allowed.size()) ? " or " : ", ";
    s += allowed[i];
  }
  return s;
}

}  // namespace tribex::inputs
