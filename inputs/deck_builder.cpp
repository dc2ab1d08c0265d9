// SPDX-License-Identifier: MIT
#include "inputs/deck_builder.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <span>

#include "contact/laws/contact_law.hpp"
#include "inputs/declared_keys.hpp"
#include "inputs/did_you_mean.hpp"
#include "inputs/lexer.hpp"
#include "materials/material.hpp"

namespace tribex::inputs {
namespace {

Dimension add(Dimension a, Dimension b) { return {a.mass + b.mass, a.length + b.length, a.time + b.time}; }

std::string line_of(const SourceLocation& w) { return w.file + ":" + std::to_string(w.line); }

/// What a function's `ordinate unit` says, for the dimension check where the function is used.
struct FunctionUnits {
  bool has_unit = false;
  Dimension dimension;
  SourceLocation where;
};

class Builder {
 public:
  Builder(const Scope& root, const std::string& file_name, DiagnosticSink& sink)
      : root_(root), file_name_(file_name), sink_(sink) {}

  Deck build(const Scope& root) {
    Deck deck;
    deck.path = file_name_;
    const auto sierras = root.children_of("sierra");
    if (sierras.empty()) return deck;
    const Scope& sierra = *sierras.front();
    deck.name = sierra.name;
    for (const Scope* f : sierra.children_of("function")) deck.functions.push_back(function(*f));
    for (const Scope* m : sierra.children_of("property specification for material")) {
      deck.materials.push_back(material(*m));
    }
    for (const Scope* s : sierra.children_of("solid section")) deck.sections.push_back(section(*s));
    for (const Scope* m : sierra.children_of("finite element model")) deck.models.push_back(model(*m, deck));
    for (const Scope* p : sierra.children_of("presto procedure")) deck.procedure = procedure(*p, deck);
    return deck;
  }

 private:
  // ---- reading values (the tree already checked kind, dimension and range) ----
  static std::optional<Value> get(const Scope& s, const std::string& key) {
    if (const KeyLine* k = s.find(key)) return k->value;
    return default_value(*s.schema->key(key));
  }
  static double real(const Scope& s, const std::string& key, double fallback = 0.0) {
    auto v = get(s, key);
    return v && !v->numbers.empty() ? v->numbers[0] : fallback;
  }
  static std::optional<double> optional_real(const Scope& s, const std::string& key) {
    auto v = get(s, key);
    if (v && !v->numbers.empty()) return v->numbers[0];
    return std::nullopt;
  }
  static std::string word(const Scope& s, const std::string& key) {
    auto v = get(s, key);
    return v && !v->words.empty() ? v->words[0] : std::string();
  }
  static std::vector<std::string> words(const Scope& s, const std::string& key) {
    auto v = get(s, key);
    return v ? v->words : std::vector<std::string>{};
  }
  static SourceLocation where(const Scope& s, const std::string& key) {
    const KeyLine* k = s.find(key);
    return k ? k->where : s.where;
  }
  void error(const SourceLocation& w, const Scope& s, const std::string& message) { sink_.error(w, s.path, message); }

  // Reports a reference to a name that is not defined, with a did-you-mean among `known`.
  template <class Specs>
  bool check_reference(const Scope& s, const std::string& key, const std::string& what, const Specs& known) {
    const std::string name = word(s, key);
    if (name.empty()) return false;  // missing or bad: already reported
    std::vector<std::string> names;
    for (const auto& k : known) {
      if (k.name == name) return true;
      if (!k.name.empty()) names.push_back(k.name);
    }
    for (const auto& [type, rejected] : root_.rejected_blocks) {
      if (type == what && rejected == name) return false;  // its block was already reported
    }
    const std::string hint = closest_match(name, names);
    error(where(s, key), s,
          "'" + key + "': no " + what + " named '" + name + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?") +
              (names.empty() ? "; define it with 'begin " + what + " " + name + "'"
                             : "; defined: " + join_choices(names)));
    return false;
  }

  // ---- blocks ----
  FunctionSpec function(const Scope& s) {
    FunctionSpec f;
    f.name = s.name;
    f.where = s.where;
    const double fx = real(s, "abscissa unit", 1.0);
    const double fy = real(s, "ordinate unit", 1.0);
    FunctionUnits units;
    if (const KeyLine* k = s.find("ordinate unit"); k && k->value) {
      units = {true, k->value->dimension, k->where};
    }
    function_units_[f.name] = units;
    for (const Scope* values : s.children_of("values")) {
      if (values->rows.size() < 2) {
        error(values->where, *values,
              "'begin values' of function '" + f.name + "' needs at least 2 rows 't f(t)', got " +
                  std::to_string(values->rows.size()));
      }
      for (const auto& r : values->rows) {
        const double t = r.numbers[0] * fx;
        if (!f.abscissa.empty() && !(t > f.abscissa.back())) {
          error(r.where, *values, "t must be strictly increasing in 'begin values'; this row's t is not greater than the previous row's");
        }
        f.abscissa.push_back(t);
        f.ordinate.push_back(r.numbers[1] * fy);
      }
    }
    return f;
  }

  MaterialSpec material(const Scope& s) {
    MaterialSpec m;
    m.name = s.name;
    m.where = s.where;
    m.density = real(s, "density");
    m.density_where = where(s, "density");
    for (const Scope* p : s.children_of("parameters for model")) {
      MaterialModelParameters mp;
      mp.where = p->where;
      mp.model = p->name;
      mp.parameters = declared_values(*p, material_model_list(), materials::model_index(mp.model), material_wording());
      const bool e = p->find("youngs modulus"), nu = p->find("poissons ratio");
      const bool k = p->find("bulk modulus"), g = p->find("shear modulus");
      if (e && nu && !k && !g) {
        mp.youngs_modulus = real(*p, "youngs modulus");
        mp.poissons_ratio = real(*p, "poissons ratio");
      } else if (k && g && !e && !nu) {
        // E = 9KG / (3K + G), nu = (3K - 2G) / (2 (3K + G)); K, G > 0 gives -1 < nu < 0.5.
        const double kk = real(*p, "bulk modulus"), gg = real(*p, "shear modulus");
        mp.youngs_modulus = 9.0 * kk * gg / (3.0 * kk + gg);
        mp.poissons_ratio = (3.0 * kk - 2.0 * gg) / (2.0 * (3.0 * kk + gg));
      } else {
        error(p->where, *p,
              "material '" + m.name + "' model '" + p->name +
                  "': give exactly one pair of elastic constants, either 'youngs modulus' and 'poissons ratio' or "
                  "'bulk modulus' and 'shear modulus'");
      }
      m.models.push_back(mp);
    }
    return m;
  }

  // How the messages of declared_values name a model of a list and where a missing key goes: the
  // material models and the contact laws are worded differently, the checks are the same.
  struct ListWording {
    std::string (*owner)(const std::string& model);  // a model a key belongs to: 'model = a'
    std::string (*self)(const std::string& model);   // the block's model, after "not"
    std::string (*needs)(const std::string& model);  // the subject of "needs 'KEY'"
    std::string (*add_to)(const std::string& model); // where to add a missing key
    std::string other_fix;                           // the fix for a key of another model
    std::string missing_at;                          // the key whose line a missing key is reported at ("": the block's)
  };
  static const ListWording& material_wording() {
    static const ListWording w{[](const std::string& m) { return "'parameters for model " + m + "'"; },
                               [](const std::string& m) { return "'" + m + "'"; },
                               [](const std::string& m) { return "model '" + m + "'"; },
                               [](const std::string& m) { return "'begin parameters for model " + m + "'"; },
                               "remove the key or change the model", ""};
    return w;
  }
  static const ListWording& law_wording() {
    static const ListWording w{[](const std::string& m) { return "'model = " + m + "'"; },
                               [](const std::string& m) { return "'model = " + m + "'"; },
                               [](const std::string& m) { return "'model = " + m + "'"; },
                               [](const std::string&) { return std::string("the interaction"); },
                               "set the model or remove the key", "model"};
    return w;
  }

  // The values of the keys model `index` of `list` declares (inputs/keys/key_decl.hpp), by name: what the
  // block gives (SI; a path relative to the deck's folder) and the declared defaults. A key that only
  // other models of the list declare is an error naming them; so is a missing required key.
  keys::KeyValues declared_values(const Scope& s, const ModelList& list, int index, const ListWording& w) {
    if (index < 0) return {};  // not a model of the list: the schema reported the name
    const std::string& model = list.names[static_cast<std::size_t>(index)];
    const auto own = list.keys[static_cast<std::size_t>(index)];
    auto declares = [](std::span<const keys::KeyDecl> keys, const std::string& key) {
      return std::any_of(keys.begin(), keys.end(), [&](const keys::KeyDecl& k) { return k.key == key; });
    };
    std::vector<std::string> seen;
    for (const auto& other : list.keys)
      for (const keys::KeyDecl& k : other) {
        const std::string key(k.key);
        if (declares(own, key) || !s.find(key) || std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
        seen.push_back(key);
        std::string owners;
        for (std::size_t m = 0; m < list.names.size(); ++m)
          if (declares(list.keys[m], key)) owners += (owners.empty() ? "" : " or ") + w.owner(list.names[m]);
        error(where(s, key), s, "'" + key + "' applies to " + owners + ", not " + w.self(model) + "; " + w.other_fix);
      }
    keys::KeyValues values;
    for (const keys::KeyDecl& k : own) {
      const std::string key(k.key);
      if (s.find(key)) {
        if (k.unit == "path") {
          std::filesystem::path path(word(s, key));
          if (path.is_relative()) path = std::filesystem::path(s.find(key)->where.file).parent_path() / path;
          values.paths[key] = path.lexically_normal().string();
        } else {
          values.numbers[key] = real(s, key);
        }
      } else if (k.required) {
        error(w.missing_at.empty() ? s.where : where(s, w.missing_at), s,
              w.needs(model) + " needs '" + key + "' (" + std::string(k.help) + ", " +
                  std::string(k.unit.empty() ? "dimensionless" : k.unit) + "); add it to " + w.add_to(model));
      } else if (!k.default_text.empty()) {
        std::string why;  // the model's own default, in deck syntax ("0", "2 GPa"): SI
        const auto q = parse_quantity(k.default_text, &why);
        values.numbers[key] = q ? q->value : 0.0;
      }
    }
    return values;
  }

  SectionSpec section(const Scope& s) {
    SectionSpec sec;
    sec.name = s.name;
    sec.where = s.where;
    sec.formulation = word(s, "formulation") == "fully_integrated" ? ElementFormulation::fully_integrated
                                                                   : ElementFormulation::mean_quadrature;
    sec.hourglass_stiffness = real(s, "hourglass stiffness");
    sec.hourglass_viscosity = real(s, "hourglass viscosity");
    sec.linear_bulk_viscosity = real(s, "linear bulk viscosity");
    sec.quadratic_bulk_viscosity = real(s, "quadratic bulk viscosity");
    return sec;
  }

  FiniteElementModelSpec model(const Scope& s, const Deck& deck) {
    FiniteElementModelSpec m;
    m.name = s.name;
    m.where = s.where;
    const auto boxes = s.children_of("generated box");
    const auto asperities = s.children_of("generated asperity");
    const auto afm = s.children_of("afm surface");
    const bool generated = !boxes.empty() || !asperities.empty() || !afm.empty();
    const KeyLine* db = s.find("database name");
    const std::string type = word(s, "database type");
    if (db && generated) {
      error(db->where, s, "model '" + m.name + "' has both 'database name' and a generated mesh; use one");
    } else if (!db && !generated) {
      error(s.where, s, "model '" + m.name + "' needs a mesh: 'database name = FILE.msh', 'begin generated box NAME', "
                        "'begin generated asperity' or 'begin afm surface'");
    }
    for (const Scope* a : asperities) {
      GeneratedAsperitySpec g;
      g.where = a->where;
      g.radius = real(*a, "radius");
      g.tip_width = real(*a, "tip width");
      g.tip_height = real(*a, "tip height");
      g.substrate_width = real(*a, "substrate width");
      g.substrate_depth = real(*a, "substrate depth");
      g.gap = real(*a, "gap");
      g.element_size = real(*a, "element size");
      g.fine_half_width = real(*a, "fine half width");
      g.fine_depth = real(*a, "fine depth");
      g.grading_ratio = real(*a, "grading ratio");
      g.coating_thickness = real(*a, "coating thickness");
      g.coating_layers = static_cast<int>(real(*a, "coating layers"));
      g.quarter = word(*a, "symmetry") == "quarter";
      g.tip_only = word(*a, "substrate") == "none";
      g.paraboloid = word(*a, "tip profile") == "paraboloid";
      if (auto v = get(*a, "apex position"); v && v->numbers.size() == 3) g.apex = {{v->numbers[0], v->numbers[1], v->numbers[2]}};
      g.gap_above_surface = optional_real(*a, "gap above surface");
      if (auto v = get(*a, "fine x range"); v && v->numbers.size() == 2) g.fine_x_range = {{v->numbers[0], v->numbers[1]}};
      for (const char* key : {"radius", "tip width", "tip height", "substrate width", "substrate depth", "gap", "element size",
                              "fine half width", "fine depth", "fine x range", "grading ratio", "coating thickness",
                              "coating layers", "symmetry"})
        if (const KeyLine* k = a->find(key)) g.key_where[key] = k->where;
      if (g.gap_above_surface && (!g.tip_only || afm.empty()))
        error(where(*a, "gap above surface"), *a,
              "'gap above surface' places a tip over an 'afm surface': it needs 'substrate = none' and a 'begin afm "
              "surface' in the same finite element model; use 'gap' for the generated substrate");
      m.asperity = g;
    }
    if (db) {
      std::filesystem::path p(word(s, "database name"));
      // Exodus II by the extension (.exo .e .g .gen, any case) unless the type says otherwise.
      std::string ext = p.extension().string();
      for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      const bool exodus_name = ext == ".exo" || ext == ".e" || ext == ".g" || ext == ".gen";
      m.source = type == "exodus" || (type.empty() && exodus_name) ? FiniteElementModelSpec::Source::exodus
                                                                    : FiniteElementModelSpec::Source::gmsh;
      if (p.is_relative()) p = std::filesystem::path(db->where.file).parent_path() / p;
      m.database_path = p.lexically_normal().string();
      if (type == "generated") error(where(s, "database type"), s, "'database type = generated' but 'database name' is given; use 'gmsh' or 'exodus', or drop the key");
    } else {
      m.source = FiniteElementModelSpec::Source::generated;
      if (type == "gmsh" || type == "exodus")
        error(where(s, "database type"), s, "'database type = " + type + "' needs 'database name = FILE" +
                                                (type == "gmsh" ? ".msh" : ".exo") + "'");
    }
    for (const Scope* b : boxes) {
      GeneratedBoxSpec box;
      box.block_name = b->name;
      box.where = b->where;
      if (auto v = get(*b, "origin"); v && v->numbers.size() == 3) box.origin = {v->numbers[0], v->numbers[1], v->numbers[2]};
      if (auto v = get(*b, "size"); v && v->numbers.size() == 3) box.size = {v->numbers[0], v->numbers[1], v->numbers[2]};
      if (auto v = get(*b, "intervals"); v && v->numbers.size() == 3) {
        box.intervals = {static_cast<int>(v->numbers[0]), static_cast<int>(v->numbers[1]), static_cast<int>(v->numbers[2])};
      }
      box.grade_toward = word(*b, "grade toward");
      box.grading_ratio = real(*b, "grading ratio", 1.0);
      m.boxes.push_back(box);
    }
    for (const Scope* a : afm) m.afm_surface = afm_surface(*a);
    for (const Scope* b : s.children_of("surface layer block")) {
      SurfaceLayerBlockSpec sl;
      sl.name = b->name;
      sl.where = b->where;
      sl.from_block = word(*b, "from block");
      sl.surface = word(*b, "surface");
      sl.from_block_where = where(*b, "from block");
      sl.surface_where = where(*b, "surface");
      sl.layers = static_cast<int>(real(*b, "layers", 1));
      m.surface_layers.push_back(sl);
    }
    for (const Scope* b : s.children_of("parameters for block")) {
      BlockParameters bp;
      bp.block = b->name;
      bp.where = b->where;
      bp.material = word(*b, "material");
      bp.section = word(*b, "section");
      bp.model = word(*b, "model");
      if (check_reference(*b, "material", "property specification for material", deck.materials)) {
        const MaterialSpec* mat = deck.find_material(bp.material);
        bool defined = false;
        for (const auto& mp : mat->models) defined = defined || mp.model == bp.model;
        if (!defined) {
          const std::string& model_name = bp.model;
          error(where(*b, "model"), *b,
                "material '" + bp.material + "' (" + line_of(mat->where) + ") does not define model '" + model_name +
                    "'; add 'begin parameters for model " + model_name + "' to it or change 'model'");
        }
      }
      check_reference(*b, "section", "solid section", deck.sections);
      m.blocks.push_back(bp);
    }
    return m;
  }

  static AfmSurfaceSpec afm_surface(const Scope& a) {
    AfmSurfaceSpec spec;
    spec.where = a.where;
    std::filesystem::path p(word(a, "file"));
    if (p.is_relative()) p = std::filesystem::path(where(a, "file").file).parent_path() / p;
    spec.file = p.lexically_normal().string();
    if (auto c = optional_real(a, "channel")) spec.channel = static_cast<int>(*c);
    for (const char* key : {"window", "track"}) {
      if (auto v = get(a, key); v && v->numbers.size() == 4) {
        (std::string(key) == "window" ? spec.window : spec.track) =
            std::array<double, 4>{v->numbers[0], v->numbers[1], v->numbers[2], v->numbers[3]};
      }
    }
    spec.element_size = real(a, "element size", spec.element_size);
    spec.depth = real(a, "depth", spec.depth);
    spec.coating_thickness = real(a, "coating thickness", 0.0);
    spec.coating_layers = static_cast<int>(real(a, "coating layers", 6));
    spec.grading_ratio = real(a, "grading ratio", 1.3);
    spec.interpolate_small_window = word(a, "small window") == "interpolate";
    return spec;
  }

  ProcedureSpec procedure(const Scope& s, const Deck& deck) {
    ProcedureSpec p;
    p.name = s.name;
    p.where = s.where;
    for (const Scope* tc : s.children_of("time control")) {
      TimeControlSpec& t = p.time_control;
      t.where = tc->where;
      t.start_time = real(*tc, "start time");
      t.termination_time = real(*tc, "termination time");
      t.time_step_scale_factor = real(*tc, "time step scale factor", 0.9);
      t.maximum_time_step = optional_real(*tc, "maximum time step");
      t.exact_viscous_dissipation = word(*tc, "viscous dissipation") == "exact";
      if (tc->find("termination time") && !(t.termination_time > t.start_time)) {
        error(where(*tc, "termination time"), *tc,
              "'termination time' must be greater than 'start time' (" + format_seconds(t.start_time) + ")");
      }
    }
    time_control_ = &p.time_control;  // the output increments are checked against its span (schedule())
    for (const Scope* r : s.children_of("presto region")) p.region = region(*r, deck);
    time_control_ = nullptr;
    return p;
  }

  static std::string format_seconds(double t) {
    char b[40];
    std::snprintf(b, sizeof b, "%g s", t);
    return b;
  }

  // The dimension of `scale factor * f(t)` must be the one the use needs; plain numbers are SI
  // of that use, so only written units are checked.
  void check_function_use(const Scope& s, const Dimension& needed, const std::string& use, const Deck& deck) {
    if (!check_reference(s, "function", "function", deck.functions)) return;
    const std::string name = word(s, "function");
    const FunctionUnits& fu = function_units_[name];
    Dimension product = dim::none;
    bool any_unit = false;
    if (fu.has_unit) {
      product = add(product, fu.dimension);
      any_unit = true;
    }
    const KeyLine* scale = s.find("scale factor");
    if (scale && scale->value && scale->value->has_unit) {
      product = add(product, scale->value->dimension);
      any_unit = true;
    }
    if (any_unit && !(product == needed)) {
      error(scale && scale->value && scale->value->has_unit ? scale->where : where(s, "function"), s,
            use + " needs " + describe_dimension(needed) + ", but function '" + name + "'" +
                (fu.has_unit ? " (ordinate unit at " + line_of(fu.where) + ")" : "") + " times 'scale factor' gives " +
                describe_dimension(product) + "; fix the 'ordinate unit' or the unit of 'scale factor'");
    }
  }

  static Component component(const std::string& c) {
    return c == "y" ? Component::y : c == "z" ? Component::z : Component::x;
  }

  // `begin rigid body NAME`: a node set or a block, the reference point, the rotation (fixed, or free per axis).
  RigidBodySpec rigid_body(const Scope& c) {
    RigidBodySpec b;
    b.name = c.name;
    b.where = c.where;
    b.node_set = word(c, "node set");
    b.block = word(c, "block");
    if (c.find("node set") && c.find("block"))
      error(where(c, "block"), c, "'begin rigid body' takes 'node set' or 'block', not both; remove one");
    else if (!c.find("node set") && !c.find("block"))
      error(c.where, c, "'begin rigid body " + c.name + "' needs 'node set = NAME' or 'block = NAME' (its nodes)");
    if (auto p = get(c, "reference point"); p && p->numbers.size() == 3)
      b.reference_point = std::array<double, 3>{p->numbers[0], p->numbers[1], p->numbers[2]};
    b.rotation_free = word(c, "rotation") == "free";
    if (c.find("rotation axes")) {
      b.free_axes = {false, false, false};
      for (const auto& w : words(c, "rotation axes")) b.free_axes[static_cast<int>(component(w))] = true;
      // The default, x y z, stands in every resolved deck (log.txt), fixed bodies' included.
      if (!b.rotation_free && !(b.free_axes[0] && b.free_axes[1] && b.free_axes[2]))
        error(where(c, "rotation axes"), c,
              "'rotation axes' names the axes a 'rotation = free' body turns about; add 'rotation = free' or remove it");
    }
    return b;
  }

  // `begin prescribed rotation | angular velocity`: a body of the region, about an axis its rotation is
  // not free about, one drive per body and axis.
  PrescribedRotationSpec prescribed_rotation(const Scope& c, const std::string& t, const RegionSpec& r,
                                             const Deck& deck) {
    PrescribedRotationSpec p;
    const bool angle = t == "prescribed rotation";
    p.kind = angle ? PrescribedRotationSpec::Kind::angle : PrescribedRotationSpec::Kind::angular_velocity;
    p.rigid_body = word(c, "rigid body");
    p.component = component(word(c, "component"));
    p.function = word(c, "function");
    p.scale_factor = real(c, "scale factor", 1.0) * (word(c, "angle unit") == "deg" ? 3.14159265358979323846 / 180.0 : 1.0);
    p.where = c.where;
    check_function_use(c, angle ? dim::none : dim::rate, "'begin " + t + "'", deck);
    const auto body = std::find_if(r.rigid_bodies.begin(), r.rigid_bodies.end(),
                                   [&](const RigidBodySpec& b) { return b.name == p.rigid_body; });
    const int axis = static_cast<int>(p.component);
    if (body == r.rigid_bodies.end()) {
      if (c.find("rigid body"))
        error(where(c, "rigid body"), c,
              "rigid body '" + p.rigid_body + "' is not defined in the region; add 'begin rigid body " + p.rigid_body +
                  "' (with 'node set' or 'block') to it" + did_you_mean_body(r, p.rigid_body));
    } else if (body->rotation_free && body->free_axes[axis]) {
      error(where(c, "component"), c,
            "'begin " + t + "' drives rigid body '" + p.rigid_body + "' about " + "xyz"[axis] +
                ", an axis its rotation is free about ('rotation = free' at " + line_of(body->where) +
                "); drive a held axis, or hold this one ('rotation axes' without " + "xyz"[axis] +
                ", or 'rotation = fixed')");
    }
    for (const auto& q : r.prescribed_rotations)
      if (q.rigid_body == p.rigid_body && q.component == p.component)
        error(where(c, "component"), c,
              "rigid body '" + p.rigid_body + "' is already driven about " + "xyz"[axis] + " at " + line_of(q.where) +
                  "; drive each axis once");
    return p;
  }

  static std::string did_you_mean_body(const RegionSpec& r, const std::string& name) {
    std::vector<std::string> names;
    for (const auto& b : r.rigid_bodies) names.push_back(b.name);
    const std::string hint = closest_match(name, names);
    return hint.empty() ? std::string() : " (did you mean '" + hint + "'?)";
  }

  // A boundary condition's target: `node set = NAME` or `rigid body = NAME` (exactly one). A rigid
  // body's nodes are the node set NAME that build_mesh adds for it, so the node-set machinery applies
  // the condition to every node of the body; `rigid_body` keeps the name for the body's own accounts.
  void target(const Scope& c, const std::string& block, const RegionSpec& r, std::string& node_set,
              std::string& rigid_body) {
    node_set = word(c, "node set");
    rigid_body = word(c, "rigid body");
    if (c.find("node set") && c.find("rigid body")) {
      error(where(c, "rigid body"), c, block + " takes 'node set' or 'rigid body', not both; remove one");
    } else if (!c.find("node set") && !c.find("rigid body")) {
      error(c.where, c, block + " needs 'node set = NAME' or 'rigid body = NAME'");
    } else if (!rigid_body.empty()) {
      const bool known = std::any_of(r.rigid_bodies.begin(), r.rigid_bodies.end(),
                                     [&](const RigidBodySpec& b) { return b.name == rigid_body; });
      if (!known)
        error(where(c, "rigid body"), c,
              "rigid body '" + rigid_body + "' is not defined in the region; add 'begin rigid body " + rigid_body +
                  "' (with 'node set' or 'block') to it" + did_you_mean_body(r, rigid_body));
      node_set = rigid_body;
    }
  }

  RegionSpec region(const Scope& s, const Deck& deck) {
    RegionSpec r;
    r.name = s.name;
    r.where = s.where;
    r.finite_element_model = word(s, "use finite element model");
    check_reference(s, "use finite element model", "finite element model", deck.models);
    r.mass_damping_coefficient = real(s, "mass damping coefficient");
    r.guards.energy_error_warning = real(s, "energy error warning");
    r.guards.energy_error_limit = optional_real(s, "energy error limit");
    r.guards.penetration_warning = real(s, "penetration warning");
    if (auto v = get(s, "quasi static")) r.guards.quasi_static = v->flag;
    r.guards.kinetic_energy_warning = real(s, "kinetic energy warning");
    r.guards.contact_motion_warning = real(s, "contact motion warning");
    r.guards.contact_motion_limit = real(s, "contact motion limit");
    for (const Scope& c : s.children)
      if (c.type() == "rigid body") r.rigid_bodies.push_back(rigid_body(c));
    for (const Scope& c : s.children) {
      const std::string& t = c.type();
      if (t == "fixed displacement") {
        FixedDisplacementSpec f;
        f.node_set = word(c, "node set");
        for (const auto& w : words(c, "components")) f.components.push_back(component(w));
        f.where = c.where;
        r.fixed_displacements.push_back(f);
      } else if (t == "prescribed displacement" || t == "prescribed velocity") {
        PrescribedMotionSpec m;
        const bool velocity = t == "prescribed velocity";
        m.kind = velocity ? PrescribedMotionSpec::Kind::velocity : PrescribedMotionSpec::Kind::displacement;
        target(c, "'begin " + t + "'", r, m.node_set, m.rigid_body);
        m.component = component(word(c, "component"));
        m.function = word(c, "function");
        m.scale_factor = real(c, "scale factor", 1.0);
        m.where = c.where;
        check_function_use(c, velocity ? dim::velocity : dim::length, "'begin " + t + "'", deck);
        r.prescribed_motions.push_back(m);
      } else if (t == "initial velocity") {
        InitialVelocitySpec v;
        v.node_set = word(c, "node set");
        v.block = word(c, "block");
        if (c.find("node set") && c.find("block")) {
          error(where(c, "block"), c, "'begin initial velocity' takes 'node set' or 'block', not both; remove one");
        } else if (!c.find("node set") && !c.find("block")) {
          error(c.where, c, "'begin initial velocity' needs 'node set = NAME' or 'block = NAME'");
        }
        if (auto vel = get(c, "velocity"); vel && vel->numbers.size() == 3) {
          v.velocity = {vel->numbers[0], vel->numbers[1], vel->numbers[2]};
        }
        v.where = c.where;
        r.initial_velocities.push_back(v);
      } else if (t == "pressure") {
        PressureSpec p;
        p.side_set = word(c, "side set");
        p.function = word(c, "function");
        p.scale_factor = real(c, "scale factor", 1.0);
        p.where = c.where;
        check_function_use(c, dim::pressure, "'begin pressure'", deck);
        r.pressures.push_back(p);
      } else if (t == "prescribed force") {
        PrescribedForceSpec p;
        target(c, "'begin prescribed force'", r, p.node_set, p.rigid_body);
        p.component = component(word(c, "component"));
        p.function = word(c, "function");
        p.scale_factor = real(c, "scale factor", 1.0);
        p.where = c.where;
        check_function_use(c, dim::force, "'begin prescribed force'", deck);
        r.prescribed_forces.push_back(p);
      } else if (t == "prescribed rotation" || t == "prescribed angular velocity") {
        r.prescribed_rotations.push_back(prescribed_rotation(c, t, r, deck));
      } else if (t == "rigid body") {
        // read before the loop (a boundary condition may name a body defined below it)
      } else if (t == "silent boundary") {
        SilentBoundarySpec b;
        b.side_set = word(c, "side set");
        b.normal_coefficient = real(c, "normal coefficient", 1.0);
        b.tangential_coefficient = real(c, "tangential coefficient", 1.0);
        b.where = c.where;
        r.silent_boundaries.push_back(b);
      } else if (t == "contact definition") {
        r.contact = contact(c);
      } else if (t == "results output") {
        ResultsOutputSpec o;
        schedule(c, o);
        o.nodal_variables = words(c, "nodal variables");
        o.element_variables = words(c, "element variables");
        const std::string format = word(c, "format");
        o.xdmf = format != "exodus";
        o.exodus = format == "exodus" || format == "both";
        o.length_unit = word(c, "length unit");
        r.results = o;
      } else if (t == "history output") {
        HistoryOutputSpec o;
        schedule(c, o);
        o.reaction_force_node_sets = words(c, "reaction force");
        o.displacement_node_sets = words(c, "mean displacement");
        o.reaction_force_where = where(c, "reaction force");
        o.displacement_where = where(c, "mean displacement");
        r.history = o;
      } else if (t == "restart output") {
        RestartOutputSpec o;
        o.where = c.where;
        if (auto n = optional_real(c, "step increment")) o.step_increment = static_cast<int>(*n);
        o.wall_time_increment = optional_real(c, "wall time increment");
        o.ring_size = static_cast<int>(real(c, "ring size", 2.0));
        if (!o.step_increment && !o.wall_time_increment)
          error(c.where, c, "'begin restart output' needs 'step increment = N' and/or 'wall time increment = T'");
        r.restart = o;
      } else if (t == "mass scaling") {
        r.mass_scaling = mass_scaling(c, r.guards);
      } else if (t == "decomposition") {
        r.decomposition.where = c.where;
        const std::string method = word(c, "method");
        if (method == "metis") r.decomposition.method = DecompositionSpec::Method::metis;
        if (method == "rcb") r.decomposition.method = DecompositionSpec::Method::rcb;
        if (method == "ptscotch") r.decomposition.method = DecompositionSpec::Method::ptscotch;
        if (auto n = optional_real(c, "distributed above")) r.decomposition.distributed_above = static_cast<int>(*n);
        if (word(c, "set-up") == "distributed") {
          if (r.decomposition.method != DecompositionSpec::Method::ptscotch)
            error(where(c, "set-up"), c, "'set-up = distributed' needs 'method = ptscotch' (the partition by all the ranks)");
          r.decomposition.distributed_setup = true;
        }
        if (auto scale = get(c, "coordinate scale"); scale && scale->numbers.size() == 3)
          r.decomposition.coordinate_scale = std::array<double, 3>{scale->numbers[0], scale->numbers[1], scale->numbers[2]};
      }
    }
    return r;
  }

  // `begin mass scaling`: one target (a time step or a factor); the kinetic-energy limit belongs to
  // quasi-static runs (a dynamic run has kinetic energy by nature) and is 0.1 there unless given.
  MassScalingSpec mass_scaling(const Scope& c, GuardSpec& guards) {
    MassScalingSpec m;
    m.where = c.where;
    m.target_time_step = optional_real(c, "target time step");
    m.largest_factor = optional_real(c, "largest factor");
    m.target_where = where(c, m.target_time_step ? "target time step" : "largest factor");
    if (m.target_time_step && m.largest_factor)
      error(where(c, "largest factor"), c,
            "'begin mass scaling' takes 'target time step' or 'largest factor', not both; remove one");
    else if (!m.target_time_step && !m.largest_factor)
      error(c.where, c, "'begin mass scaling' needs 'target time step = DT' or 'largest factor = F'");
    m.blocks = words(c, "blocks");
    m.blocks_where = where(c, "blocks");
    m.maximum_added_mass_fraction = real(c, "maximum added mass fraction", 0.05);
    m.maximum_kinetic_energy_ratio = optional_real(c, "maximum kinetic energy ratio");
    if (m.maximum_kinetic_energy_ratio && !guards.quasi_static)
      error(where(c, "maximum kinetic energy ratio"), c,
            "'maximum kinetic energy ratio' applies to quasi-static runs: add 'quasi static = on' to the region or "
            "remove the key");
    if (guards.quasi_static) guards.kinetic_energy_limit = m.maximum_kinetic_energy_ratio.value_or(0.1);
    return m;
  }

  // `begin contact definition`: surfaces from `contact surface NAME contains SIDESET...` lines,
  // interactions naming two of them.
  ContactSpec contact(const Scope& c) {
    ContactSpec spec;
    spec.name = c.name;
    spec.where = c.where;
    for (const auto& k : c.keys) {
      if (k.schema->name != "contact surface" || !k.value) continue;
      const auto& w = k.value->words;
      if (w.size() < 3 || lower(w[1]) != "contains") {
        error(k.where, c, "write 'contact surface NAME contains SIDESET [SIDESET ...]'");
        continue;
      }
      for (const auto& existing : spec.surfaces)
        if (existing.name == w[0]) error(k.where, c, "contact surface '" + w[0] + "' is defined twice (first at " + line_of(existing.where) + ")");
      spec.surfaces.push_back({w[0], std::vector<std::string>(w.begin() + 2, w.end()), k.where});
    }
    spec.penalty_scale_factor = real(c, "penalty scale factor", 1.0);
    spec.search_margin = optional_real(c, "search margin");
    spec.initial_overlap_tolerance = optional_real(c, "initial overlap tolerance");
    if (auto axis = get(c, "contact axis"); axis && axis->numbers.size() == 6) {
      std::array<double, 6> a{};
      std::copy(axis->numbers.begin(), axis->numbers.end(), a.begin());
      if (a[3] == 0.0 && a[4] == 0.0 && a[5] == 0.0) error(where(c, "contact axis"), c, "the axis direction (last three numbers) must not be zero");
      spec.axis = a;
    }
    std::vector<std::string> names;
    for (const auto& sf : spec.surfaces) names.push_back(sf.name);
    for (const Scope* it : c.children_of("interaction")) {
      InteractionSpec i;
      i.name = it->name;
      i.where = it->where;
      const auto w = words(*it, "surfaces");
      if (w.size() != 2) {
        error(where(*it, "surfaces"), *it, "'surfaces' takes two contact surface names: SLAVE MASTER");
      } else {
        i.slave = w[0];
        i.master = w[1];
        for (const auto& n : w)
          if (std::find(names.begin(), names.end(), n) == names.end()) {
            const std::string hint = closest_match(n, names);
            error(where(*it, "surfaces"), *it, "no contact surface named '" + n + "'" +
                      (hint.empty() ? "" : "; did you mean '" + hint + "'?") + "; defined: " +
                      (names.empty() ? std::string("none") : join_choices(names)));
          }
        if (w[0] == w[1]) error(where(*it, "surfaces"), *it, "an interaction needs two different surfaces");
      }
      if (auto v = get(*it, "symmetric")) i.symmetric = v->flag;
      if (word(*it, "enforcement") == "mortar") i.enforcement = InteractionEnforcement::mortar;
      interaction_law(*it, i);
      force_direction(*it, i, spec.axis.has_value());
      spec.interactions.push_back(i);
    }
    return spec;
  }

  // `model = LAW` and the law's keys (contact/laws/contact_law.hpp, declared_values above); the law's own
  // rules between its keys are checked here (so a deck `check` accepts sets up), and so is the enforcement.
  void interaction_law(const Scope& it, InteractionSpec& i) {
    i.model = word(it, "model");
    if (i.model.empty()) i.model = "frictionless";
    const int law = contact::law_index(i.model);
    if (law < 0) return;  // the schema reported the choice
    i.values = declared_values(it, contact_law_list(), law, law_wording());
    for (const keys::KeyDecl& k : contact::law_keys(law))
      if (it.find(std::string(k.key))) i.key_where[std::string(k.key)] = where(it, std::string(k.key));
    if (const auto problem = contact::check_law(law, i.values))
      error(problem->key.empty() ? where(it, "model") : where(it, problem->key), it, problem->message);
    if (i.enforcement == InteractionEnforcement::mortar) {
      const std::string why = contact::mortar_problem(law);
      if (!why.empty()) error(where(it, "enforcement"), it, why);
    }
  }

  // `force direction = axis`: the penalty force along the contact axis. Only where it means one thing: the
  // node-to-face penalty of frictionless contact (a law's own forces and the mortar's keep their normals),
  // with the axis given in the contact definition.
  void force_direction(const Scope& it, InteractionSpec& i, bool has_axis) {
    if (word(it, "force direction") != "axis") return;
    i.force_along_axis = true;
    if (!has_axis)
      error(where(it, "force direction"), it, "'force direction = axis' needs 'contact axis = px py pz dx dy dz' in the contact definition");
    else if (i.enforcement != InteractionEnforcement::node_to_face || i.model != "frictionless")
      error(where(it, "force direction"), it,
            "'force direction = axis' is for 'model = frictionless' with 'enforcement = node to face'; remove it");
  }

  template <class Output>
  void schedule(const Scope& c, Output& o) {
    o.where = c.where;
    o.time_increment = optional_real(c, "time increment");
    if (auto n = optional_real(c, "step increment")) o.step_increment = static_cast<int>(*n);
    const bool time = c.find("time increment"), step = c.find("step increment");
    if (time && step) {
      error(where(c, "step increment"), c,
            "'begin " + c.type() + "' takes 'time increment' or 'step increment', not both; remove one");
    } else if (!time && !step) {
      error(c.where, c, "'begin " + c.type() + "' needs 'time increment = T' or 'step increment = N'");
    } else if (time && o.time_increment && time_control_) {
      check_output_count(c, *o.time_increment);
    }
  }

  // Every loop bounded (issue 54, item 9): a time increment may give at most kMaxOutputTimes output
  // times over the run, and must be resolvable at the run's times (t + dt > t in doubles).
  void check_output_count(const Scope& c, double dt) {
    const TimeControlSpec& tc = *time_control_;
    const double span = tc.termination_time - tc.start_time;
    if (!(span > 0)) return;  // reported with the time control
    const double outputs = span / dt;
    const double largest_time = std::max(std::fabs(tc.start_time), std::fabs(tc.termination_time));
    char b[320];
    if (!(outputs <= kMaxOutputTimes)) {
      std::snprintf(b, sizeof b,
                    "'time increment' %g s gives %.3g output times over the run (%g s to %g s), more than the "
                    "limit of %.0e; give a time increment of at least %g s, or 'step increment = N'",
                    dt, outputs, tc.start_time, tc.termination_time, kMaxOutputTimes, span / kMaxOutputTimes);
      error(where(c, "time increment"), c, b);
    } else if (dt < 1e-12 * largest_time) {
      std::snprintf(b, sizeof b,
                    "'time increment' %g s is below the resolution of the run's times (1e-12 x %g s); give a "
                    "time increment of at least %g s, or 'step increment = N'",
                    dt, largest_time, 1e-12 * largest_time);
      error(where(c, "time increment"), c, b);
    }
  }
  static constexpr double kMaxOutputTimes = 1e8;  // history rows or results steps of one output block

  const Scope& root_;
  std::string file_name_;
  DiagnosticSink& sink_;
  std::map<std::string, FunctionUnits> function_units_;
  const TimeControlSpec* time_control_ = nullptr;  // while the procedure's region is built
};

}  // namespace

Deck build_deck(const Scope& root, const std::string& file_name, DiagnosticSink& sink) {
  return Builder(root, file_name, sink).build(root);
}

}  // namespace tribex::inputs
