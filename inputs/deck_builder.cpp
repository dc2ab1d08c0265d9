// SPDX-License-Identifier: MIT
#include "inputs/deck_builder.hpp"

#include <filesystem>
#include <map>

#include "inputs/did_you_mean.hpp"

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
    for (const Scope* p : s.children_of("parameters for model")) {
      MaterialModelParameters mp;
      mp.where = p->where;
      mp.model = p->name == "neo_hookean" ? MaterialModel::neo_hookean : MaterialModel::elastic;
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
    const KeyLine* db = s.find("database name");
    const std::string type = word(s, "database type");
    if (db && !boxes.empty()) {
      error(db->where, s, "model '" + m.name + "' has both 'database name' and 'begin generated box'; use one");
    } else if (!db && boxes.empty()) {
      error(s.where, s, "model '" + m.name + "' needs a mesh: 'database name = FILE.msh' or 'begin generated box NAME'");
    }
    if (db) {
      m.source = FiniteElementModelSpec::Source::gmsh;
      std::filesystem::path p(word(s, "database name"));
      if (p.is_relative()) p = std::filesystem::path(db->where.file).parent_path() / p;
      m.database_path = p.lexically_normal().string();
      if (type == "generated") error(where(s, "database type"), s, "'database type = generated' but 'database name' is given; use 'gmsh' or drop the key");
    } else {
      m.source = FiniteElementModelSpec::Source::generated;
      if (type == "gmsh") error(where(s, "database type"), s, "'database type = gmsh' needs 'database name = FILE.msh'");
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
    for (const Scope* b : s.children_of("parameters for block")) {
      BlockParameters bp;
      bp.block = b->name;
      bp.where = b->where;
      bp.material = word(*b, "material");
      bp.section = word(*b, "section");
      bp.model = word(*b, "model") == "neo_hookean" ? MaterialModel::neo_hookean : MaterialModel::elastic;
      if (check_reference(*b, "material", "property specification for material", deck.materials)) {
        const MaterialSpec* mat = deck.find_material(bp.material);
        bool defined = false;
        for (const auto& mp : mat->models) defined = defined || mp.model == bp.model;
        if (!defined) {
          const std::string model_name = bp.model == MaterialModel::neo_hookean ? "neo_hookean" : "elastic";
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
      if (tc->find("termination time") && !(t.termination_time > t.start_time)) {
        error(where(*tc, "termination time"), *tc,
              "'termination time' must be greater than 'start time' (" + format_seconds(t.start_time) + ")");
      }
    }
    for (const Scope* r : s.children_of("presto region")) p.region = region(*r, deck);
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

  RegionSpec region(const Scope& s, const Deck& deck) {
    RegionSpec r;
    r.name = s.name;
    r.where = s.where;
    r.finite_element_model = word(s, "use finite element model");
    check_reference(s, "use finite element model", "finite element model", deck.models);
    r.mass_damping_coefficient = real(s, "mass damping coefficient");
    r.energy_error_limit = optional_real(s, "energy error limit");
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
        m.node_set = word(c, "node set");
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
      } else if (t == "silent boundary") {
        SilentBoundarySpec b;
        b.side_set = word(c, "side set");
        b.normal_coefficient = real(c, "normal coefficient", 1.0);
        b.tangential_coefficient = real(c, "tangential coefficient", 1.0);
        b.where = c.where;
        r.silent_boundaries.push_back(b);
      } else if (t == "results output") {
        ResultsOutputSpec o;
        schedule(c, o);
        o.nodal_variables = words(c, "nodal variables");
        o.element_variables = words(c, "element variables");
        r.results = o;
      } else if (t == "history output") {
        HistoryOutputSpec o;
        schedule(c, o);
        o.reaction_force_node_sets = words(c, "reaction force");
        o.displacement_node_sets = words(c, "mean displacement");
        r.history = o;
      }
    }
    return r;
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
    }
  }

  const Scope& root_;
  std::string file_name_;
  DiagnosticSink& sink_;
  std::map<std::string, FunctionUnits> function_units_;
};

}  // namespace

Deck build_deck(const Scope& root, const std::string& file_name, DiagnosticSink& sink) {
  return Builder(root, file_name, sink).build(root);
}

}  // namespace tribex::inputs
