// SPDX-License-Identifier: MIT
// The deck parser end to end: values of every block, defaults, unit conversion, grammar
// variants, errors and the resolved-text round trip. Unit conversions are exact decimal
// definitions, so numbers are compared to a relative 1e-15.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "inputs/diagnostics.hpp"

using namespace tribex::inputs;

namespace {

const std::string good_dir = std::string(TRIBEX_SOURCE_DIR) + "/tests/bad_decks/good/";

void expect_close(double got, double want) { EXPECT_NEAR(got, want, 1e-15 * std::abs(want)) << want; }

// Every problem of `text`, or an empty list when it parses.
std::vector<Diagnostic> errors_of(const std::string& text) {
  try {
    parse_deck_string(text, "d.i");
  } catch (const DeckError& e) {
    return e.diagnostics();
  }
  return {};
}

bool has_error(const std::vector<Diagnostic>& ds, int line, const std::string& text) {
  for (const auto& d : ds) {
    if (d.where.line == line && d.message.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string all(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += d.str() + "\n";
  return s;
}

// A valid deck with `body` inserted into the region (line 34 is the first line of body).
std::string deck_with_region(const std::string& body, const std::string& top = "") {
  return "begin sierra s\n"                                      // 1
         "  begin function f\n"                                  // 2
         "    type = piecewise linear\n"                         // 3
         "    begin values\n      0 0\n      1 1\n    end\n"     // 4-7
         "  end\n" +                                             // 8
         top +
         "  begin property specification for material m\n"      // 9
         "    density = 1\n"                                     // 10
         "    begin parameters for model elastic\n"              // 11
         "      youngs modulus = 1\n      poissons ratio = 0\n"  // 12-13
         "    end\n  end\n"                                      // 14-15
         "  begin solid section s\n  end\n"                      // 16-17
         "  begin finite element model fem\n    begin generated box b\n      size = 1 1 1\n"
         "      intervals = 1 1 1\n    end\n    begin parameters for block b\n      material = m\n"
         "      section = s\n    end\n  end\n"
         "  begin presto procedure p\n    begin time control\n      termination time = 1\n    end\n"
         "    begin presto region r\n      use finite element model fem\n" +
         body + "    end\n  end\nend\n";
}

TEST(Parser, FullDeckValues) {
  const Deck d = parse_deck_file(good_dir + "full.i");
  EXPECT_EQ(d.name, "tip_on_flat");
  ASSERT_EQ(d.functions.size(), 2u);
  const FunctionSpec& ramp = *d.find_function("ramp");
  ASSERT_EQ(ramp.abscissa.size(), 3u);
  expect_close(ramp.abscissa[1], 10e-12);  // abscissa unit = ps
  expect_close(ramp.ordinate[1], -2.5e-9);  // ordinate unit = nm
  EXPECT_EQ(d.find_function("load")->ordinate[1], 1e6);

  const MaterialSpec& si = *d.find_material("silicon");
  expect_close(si.density, 2330.0);
  ASSERT_EQ(si.models.size(), 2u);
  EXPECT_EQ(si.models[0].model, "elastic");
  expect_close(si.models[0].youngs_modulus, 161e9);
  expect_close(si.models[0].poissons_ratio, 0.23);
  // K = 100 GPa, G = 60 GPa: E = 9KG/(3K+G) = 150 GPa, nu = (3K-2G)/(2(3K+G)) = 0.25.
  EXPECT_EQ(si.models[1].model, "neo_hookean");
  expect_close(si.models[1].youngs_modulus, 150e9);
  expect_close(si.models[1].poissons_ratio, 0.25);

  const SectionSpec& sec = *d.find_section("hex8");
  EXPECT_EQ(sec.formulation, ElementFormulation::fully_integrated);
  EXPECT_EQ(sec.hourglass_stiffness, 0.1);
  EXPECT_EQ(sec.hourglass_viscosity, 0.01);
  EXPECT_EQ(sec.linear_bulk_viscosity, 0.05);
  EXPECT_EQ(sec.quadratic_bulk_viscosity, 1.0);

  const FiniteElementModelSpec& m = *d.find_model("tip_model");
  EXPECT_EQ(m.source, FiniteElementModelSpec::Source::generated);
  ASSERT_EQ(m.boxes.size(), 1u);
  expect_close(m.boxes[0].origin[2], -20e-9);
  expect_close(m.boxes[0].size[0], 100e-9);
  EXPECT_EQ(m.boxes[0].intervals, (std::array<int, 3>{10, 10, 4}));
  EXPECT_EQ(m.boxes[0].grade_toward, "zmax");
  EXPECT_EQ(m.boxes[0].grading_ratio, 1.1);
  ASSERT_EQ(m.blocks.size(), 2u);  // substrate and its surface layer block substrate_skin
  EXPECT_EQ(m.blocks[0].block, "substrate");
  EXPECT_EQ(m.blocks[0].material, "silicon");
  EXPECT_EQ(m.blocks[0].model, "neo_hookean");
  EXPECT_EQ(m.blocks[0].section, "hex8");
  EXPECT_EQ(m.blocks[1].block, "substrate_skin");
  EXPECT_EQ(m.blocks[1].model, "elastic");

  const TimeControlSpec& t = d.procedure.time_control;
  EXPECT_EQ(t.start_time, 0.0);
  expect_close(t.termination_time, 10e-9);
  EXPECT_EQ(t.time_step_scale_factor, 0.8);
  expect_close(t.maximum_time_step.value(), 1e-12);

  const RegionSpec& r = d.procedure.region;
  EXPECT_EQ(r.name, "tip");
  EXPECT_EQ(r.finite_element_model, "tip_model");
  ASSERT_EQ(r.fixed_displacements.size(), 1u);
  EXPECT_EQ(r.fixed_displacements[0].components, (std::vector<Component>{Component::x, Component::y, Component::z}));
  ASSERT_EQ(r.prescribed_motions.size(), 3u);  // the third drives rigid body 'cap'
  EXPECT_EQ(r.prescribed_motions[0].kind, PrescribedMotionSpec::Kind::displacement);
  EXPECT_EQ(r.prescribed_motions[0].component, Component::z);
  EXPECT_EQ(r.prescribed_motions[0].scale_factor, 2.0);
  EXPECT_EQ(r.prescribed_motions[1].kind, PrescribedMotionSpec::Kind::velocity);
  EXPECT_EQ(r.prescribed_motions[1].node_set, "substrate_xmax");
  EXPECT_TRUE(r.prescribed_motions[1].rigid_body.empty());
  EXPECT_EQ(r.prescribed_motions[2].rigid_body, "cap");
  EXPECT_EQ(r.prescribed_motions[2].node_set, "cap");  // the node set build_mesh adds for the body
  ASSERT_EQ(r.rigid_bodies.size(), 2u);
  EXPECT_EQ(r.rigid_bodies[0].name, "lid");
  EXPECT_EQ(r.rigid_bodies[0].node_set, "substrate_ymax");
  ASSERT_TRUE(r.rigid_bodies[0].reference_point.has_value());
  expect_close((*r.rigid_bodies[0].reference_point)[1], 1e-9);
  EXPECT_EQ(r.rigid_bodies[1].block, "substrate_skin");
  EXPECT_FALSE(r.rigid_bodies[1].reference_point.has_value());
  EXPECT_FALSE(r.rigid_bodies[0].rotation_free);
  EXPECT_TRUE(r.rigid_bodies[1].rotation_free);
  EXPECT_EQ(r.rigid_bodies[1].free_axes, (std::array<bool, 3>{false, false, true}));
  ASSERT_EQ(r.prescribed_rotations.size(), 2u);
  EXPECT_EQ(r.prescribed_rotations[0].kind, PrescribedRotationSpec::Kind::angle);
  EXPECT_EQ(r.prescribed_rotations[0].rigid_body, "cap");
  EXPECT_EQ(r.prescribed_rotations[0].component, Component::x);
  expect_close(r.prescribed_rotations[0].scale_factor, 1e-6 * 3.14159265358979323846 / 180.0);  // angle unit = deg
  EXPECT_EQ(r.prescribed_rotations[1].kind, PrescribedRotationSpec::Kind::angular_velocity);
  EXPECT_EQ(r.prescribed_rotations[1].component, Component::y);
  EXPECT_EQ(r.prescribed_rotations[1].scale_factor, 2.0);
  ASSERT_EQ(r.prescribed_forces.size(), 1u);
  EXPECT_EQ(r.prescribed_forces[0].rigid_body, "lid");
  ASSERT_EQ(r.initial_velocities.size(), 1u);
  EXPECT_EQ(r.initial_velocities[0].block, "substrate");
  EXPECT_TRUE(r.initial_velocities[0].node_set.empty());
  EXPECT_EQ(r.initial_velocities[0].velocity, (std::array<double, 3>{0, 0, -1}));
  ASSERT_EQ(r.pressures.size(), 1u);
  EXPECT_EQ(r.pressures[0].scale_factor, 2.0);
  EXPECT_EQ(r.pressures[0].function, "load");
  ASSERT_EQ(r.silent_boundaries.size(), 1u);
  EXPECT_EQ(r.silent_boundaries[0].normal_coefficient, 0.5);
  EXPECT_EQ(r.silent_boundaries[0].tangential_coefficient, 0.25);
  EXPECT_EQ(r.mass_damping_coefficient, 1e8);
  EXPECT_EQ(r.guards.energy_error_limit.value(), 0.1);
  ASSERT_TRUE(r.results.has_value());
  expect_close(r.results->time_increment.value(), 100e-12);
  EXPECT_FALSE(r.results->step_increment.has_value());
  EXPECT_EQ(r.results->nodal_variables.size(), 4u);
  EXPECT_EQ(r.results->element_variables, std::vector<std::string>{"stress"});
  ASSERT_TRUE(r.history.has_value());
  EXPECT_EQ(r.history->step_increment.value(), 10);
  EXPECT_EQ(r.history->reaction_force_node_sets, (std::vector<std::string>{"substrate_zmin", "substrate_zmax"}));
  EXPECT_EQ(r.history->displacement_node_sets, std::vector<std::string>{"substrate_zmax"});
  // Mesh references keep their location for the mesh layer's messages.
  EXPECT_EQ(r.fixed_displacements[0].where.line, 77);  // 68 before the surface layer block (9 lines)
}

TEST(Parser, DefaultsOfTheMinimalDeck) {
  const Deck d = parse_deck_file(good_dir + "minimal.i");
  const SectionSpec& s = d.sections.at(0);
  EXPECT_EQ(s.formulation, ElementFormulation::mean_quadrature);
  EXPECT_EQ(s.hourglass_stiffness, 0.05);
  EXPECT_EQ(s.hourglass_viscosity, 0.0);
  EXPECT_EQ(s.linear_bulk_viscosity, 0.06);
  EXPECT_EQ(s.quadratic_bulk_viscosity, 1.2);
  const GeneratedBoxSpec& b = d.models.at(0).boxes.at(0);
  EXPECT_EQ(b.origin, (std::array<double, 3>{0, 0, 0}));
  expect_close(b.size[1], 1e-3);
  EXPECT_TRUE(b.grade_toward.empty());
  EXPECT_EQ(b.grading_ratio, 1.0);
  EXPECT_EQ(d.models[0].blocks.at(0).model, "elastic");
  EXPECT_EQ(d.procedure.time_control.start_time, 0.0);
  expect_close(d.procedure.time_control.termination_time, 1e-6);
  EXPECT_EQ(d.procedure.time_control.time_step_scale_factor, 0.9);
  EXPECT_FALSE(d.procedure.time_control.maximum_time_step.has_value());
  EXPECT_EQ(d.procedure.region.mass_damping_coefficient, 0.0);
  EXPECT_FALSE(d.procedure.region.guards.energy_error_limit.has_value());
  EXPECT_FALSE(d.procedure.region.results.has_value());
  EXPECT_NE(d.resolved_text.find("hourglass stiffness = 0.05"), std::string::npos);
  EXPECT_NE(d.resolved_text.find("time step scale factor = 0.9"), std::string::npos);
}

TEST(Parser, IncludeDelimitersContinuationAndGmshPath) {
  const Deck d = parse_deck_file(good_dir + "gmsh_included.i");
  ASSERT_EQ(d.materials.size(), 1u);
  EXPECT_EQ(d.materials[0].name, "copper");
  EXPECT_EQ(d.materials[0].where.file, good_dir + "materials_part.inc");
  expect_close(d.materials[0].models.at(0).youngs_modulus, 130e9);
  EXPECT_EQ(d.models.at(0).source, FiniteElementModelSpec::Source::gmsh);
  EXPECT_EQ(d.models[0].database_path, std::string(TRIBEX_SOURCE_DIR) + "/tests/bad_decks/mesh/tip.msh");
  EXPECT_EQ(d.models[0].blocks.at(0).material, "copper");  // `material is copper`
  EXPECT_EQ(d.models[0].blocks[0].section, "sec");         // `section sec` (no delimiter)
  expect_close(d.procedure.time_control.termination_time, 2e-9);  // continued line
  EXPECT_EQ(d.procedure.region.history->reaction_force_node_sets, std::vector<std::string>{"tip_top"});
}

TEST(Parser, KeywordsAreCaseInsensitiveNamesKeepCase) {
  std::string text = deck_with_region("");
  text.replace(text.find("begin solid section s"), 21, "BEGIN Solid SECTION s");
  text.replace(text.find("begin sierra s"), 14, "Begin SIERRA MyDeck");
  const Deck d = parse_deck_string(text, "d.i");
  EXPECT_EQ(d.name, "MyDeck");
  EXPECT_EQ(d.sections.at(0).name, "s");
}

TEST(Parser, ValidRegionVariants) {
  EXPECT_EQ(all(errors_of(deck_with_region("      begin initial velocity\n        node set = top\n"
                                            "        velocity 1 2 3\n      end\n"))),
            "");
  EXPECT_EQ(all(errors_of(deck_with_region("      begin pressure\n        side set = top\n        function = f\n"
                                            "      end\n"))),
            "");
}

TEST(Parser, UnitDimensionIsCheckedAgainstTheKey) {
  const auto ds = errors_of(deck_with_region("      mass damping coefficient = 3 m\n"));
  EXPECT_TRUE(has_error(ds, 34, "expected a rate (1/s), got a length (m)")) << all(ds);
}

TEST(Parser, FunctionDimensionIsCheckedAtItsUse) {
  std::string text = deck_with_region("      begin prescribed velocity\n        node set = top\n        component = x\n"
                                      "        function = f\n      end\n");
  text.replace(text.find("    type = piecewise linear\n"), 28, "    type = piecewise linear\n    ordinate unit = nm\n");
  const auto ds = errors_of(text);
  EXPECT_TRUE(has_error(ds, 38, "needs a velocity (m/s), but function 'f'")) << all(ds);
}

TEST(Parser, EveryErrorIsCollected) {
  std::string text = deck_with_region("      mass damping coefficient = -1\n      colour = red\n");
  text.replace(text.find("density = 1"), 11, "density = 1 m");
  const auto ds = errors_of(text);
  EXPECT_EQ(ds.size(), 3u) << all(ds);
  EXPECT_TRUE(has_error(ds, 10, "expected a density (kg/m^3), got a length (m)")) << all(ds);
  EXPECT_TRUE(has_error(ds, 34, "must be >= 0")) << all(ds);
  EXPECT_TRUE(has_error(ds, 35, "unknown key 'colour'")) << all(ds);
  EXPECT_EQ(ds[0].scope, "sierra/property specification for material");
  EXPECT_EQ(ds[2].scope, "sierra/presto procedure/presto region");
}

TEST(Parser, ExactlyOneElasticPair) {
  std::string text = deck_with_region("");
  text.replace(text.find("      poissons ratio = 0\n"), 25, "      shear modulus = 1\n");
  const auto ds = errors_of(text);
  EXPECT_TRUE(has_error(ds, 11, "exactly one pair")) << all(ds);
}

TEST(Parser, ExactlyOneNodeSetOrBlockForInitialVelocity) {
  const auto ds = errors_of(deck_with_region("      begin initial velocity\n        node set = a\n        block = b\n"
                                              "        velocity = 0 0 0\n      end\n"));
  EXPECT_TRUE(has_error(ds, 36, "not both")) << all(ds);
}

TEST(Parser, ListsNeedTheirCountAndOneTrailingUnit) {
  auto ds = errors_of(deck_with_region("      begin initial velocity\n        node set = a\n"
                                       "        velocity = 0 0 m/s\n      end\n"));
  EXPECT_TRUE(has_error(ds, 36, "not a number")) << all(ds);
  ds = errors_of(deck_with_region("      begin initial velocity\n        node set = a\n"
                                  "        velocity = 0 0 1 2 m/s\n      end\n"));
  EXPECT_TRUE(has_error(ds, 36, "unexpected 'm/s'")) << all(ds);
}

// `begin prescribed force`: the function (plain numbers) times a scale factor with a force unit.
TEST(Parser, PrescribedForce) {
  const Deck d = parse_deck_string(deck_with_region("      begin prescribed force\n        node set = b_zmax\n"
                                                    "        component = z\n        function = f\n"
                                                    "        scale factor = -500 nN\n      end\n"),
                                   "pf.i");
  const auto& r = d.procedure.region;
  ASSERT_EQ(r.prescribed_forces.size(), 1u);
  EXPECT_EQ(r.prescribed_forces[0].node_set, "b_zmax");
  EXPECT_EQ(r.prescribed_forces[0].component, Component::z);
  EXPECT_EQ(r.prescribed_forces[0].function, "f");
  expect_close(r.prescribed_forces[0].scale_factor, -500e-9);
  // A length unit on the scale factor is not a force.
  auto ds = errors_of(deck_with_region("      begin prescribed force\n        node set = b_zmax\n"
                                       "        component = z\n        function = f\n"
                                       "        scale factor = 2 nm\n      end\n"));
  EXPECT_TRUE(has_error(ds, 38, "needs a force (N)")) << all(ds);  // the scale factor line
}

TEST(Parser, Decomposition) {
  // Without the block: auto from 500,000 elements, no scale (the run takes it from the contact's travel,
  // contact_travel_test).
  const Deck plain = parse_deck_string(deck_with_region(""), "plain.i");
  EXPECT_EQ(plain.procedure.region.decomposition.method, DecompositionSpec::Method::automatic);
  EXPECT_EQ(plain.procedure.region.decomposition.distributed_above, 500000);
  const Deck metis = parse_deck_string(deck_with_region("      begin decomposition\n        method = metis\n"
                                                        "        distributed above = 1000\n      end\n"),
                                       "metis.i");
  EXPECT_EQ(metis.procedure.region.decomposition.method, DecompositionSpec::Method::metis);
  EXPECT_EQ(metis.procedure.region.decomposition.distributed_above, 1000);
  EXPECT_FALSE(plain.procedure.region.decomposition.coordinate_scale.has_value());
  const Deck d = parse_deck_string(deck_with_region("      begin decomposition\n        method = rcb\n"
                                                    "        coordinate scale = 1 0.01 1\n      end\n"),
                                   "dec.i");
  const auto& dec = d.procedure.region.decomposition;
  EXPECT_EQ(dec.method, DecompositionSpec::Method::rcb);
  ASSERT_TRUE(dec.coordinate_scale.has_value());
  EXPECT_EQ(*dec.coordinate_scale, (std::array<double, 3>{1, 0.01, 1}));
  EXPECT_EQ(dec.where.line, 34);
  // PT-Scotch: the partition by all the ranks (solver/parallel/ptscotch_partition.hpp).
  const Deck pt = parse_deck_string(deck_with_region("      begin decomposition\n        method = ptscotch\n      end\n"),
                                    "pt.i");
  EXPECT_EQ(pt.procedure.region.decomposition.method, DecompositionSpec::Method::ptscotch);
  // A zero scale would put every cut on one axis; a method not in the list is named with the choices.
  auto ds = errors_of(deck_with_region("      begin decomposition\n        coordinate scale = 1 0 1\n      end\n"));
  EXPECT_TRUE(has_error(ds, 35, "coordinate scale")) << all(ds);
  ds = errors_of(deck_with_region("      begin decomposition\n        method = parmetis\n      end\n"));
  EXPECT_TRUE(has_error(ds, 35, "metis")) << all(ds);
  EXPECT_TRUE(has_error(ds, 35, "ptscotch")) << all(ds);
}

TEST(Parser, SurfaceLayerBlock) {
  const Deck d = parse_deck_file(good_dir + "full.i");
  const auto& layers = d.models.at(0).surface_layers;
  ASSERT_EQ(layers.size(), 1u);
  EXPECT_EQ(layers[0].name, "substrate_skin");
  EXPECT_EQ(layers[0].from_block, "substrate");
  EXPECT_EQ(layers[0].surface, "substrate_zmax");
  EXPECT_EQ(layers[0].layers, 2);
  EXPECT_EQ(layers[0].where.line, 52);
  EXPECT_EQ(layers[0].from_block_where.line, 53);
  EXPECT_EQ(layers[0].surface_where.line, 54);
}

TEST(Parser, ResolvedTextRoundTrips) {
  for (const char* name : {"full.i", "minimal.i", "gmsh_included.i"}) {
    const Deck first = parse_deck_file(good_dir + name);
    const Deck second = parse_deck_string(first.resolved_text, good_dir + "resolved.i");
    EXPECT_EQ(second.resolved_text, first.resolved_text) << name;
    // Spot checks of values that pass through unit conversion, defaults and aliases.
    EXPECT_EQ(second.procedure.time_control.termination_time, first.procedure.time_control.termination_time);
    EXPECT_EQ(second.procedure.time_control.time_step_scale_factor,
              first.procedure.time_control.time_step_scale_factor);
    ASSERT_EQ(second.functions.size(), first.functions.size());
    for (std::size_t i = 0; i < first.functions.size(); ++i) {
      EXPECT_EQ(second.functions[i].abscissa, first.functions[i].abscissa);
      EXPECT_EQ(second.functions[i].ordinate, first.functions[i].ordinate);
    }
    ASSERT_EQ(second.materials.size(), first.materials.size());
    for (std::size_t i = 0; i < first.materials.size(); ++i) {
      ASSERT_EQ(second.materials[i].models.size(), first.materials[i].models.size());
      for (std::size_t k = 0; k < first.materials[i].models.size(); ++k) {
        EXPECT_EQ(second.materials[i].models[k].model, first.materials[i].models[k].model);
        EXPECT_EQ(second.materials[i].models[k].youngs_modulus, first.materials[i].models[k].youngs_modulus);
        EXPECT_EQ(second.materials[i].models[k].poissons_ratio, first.materials[i].models[k].poissons_ratio);
      }
    }
    ASSERT_EQ(second.models.size(), first.models.size());
    EXPECT_EQ(second.models[0].source, first.models[0].source);
    EXPECT_EQ(second.models[0].database_path, first.models[0].database_path);
    ASSERT_EQ(second.models[0].boxes.size(), first.models[0].boxes.size());
    for (std::size_t b = 0; b < first.models[0].boxes.size(); ++b) {
      EXPECT_EQ(second.models[0].boxes[b].size, first.models[0].boxes[b].size);
      EXPECT_EQ(second.models[0].boxes[b].origin, first.models[0].boxes[b].origin);
    }
    EXPECT_EQ(second.procedure.region.prescribed_motions.size(), first.procedure.region.prescribed_motions.size());
    EXPECT_EQ(second.procedure.region.mass_damping_coefficient, first.procedure.region.mass_damping_coefficient);
  }
}

TEST(Parser, EndTextMustMatchAndMissingEndNamesTheOpening) {
  std::string text = deck_with_region("");
  text.replace(text.find("  begin solid section s\n  end\n"), 30, "  begin solid section s\n  end solid section t\n");
  auto ds = errors_of(text);
  EXPECT_TRUE(has_error(ds, 17, "does not match 'begin solid section s' at d.i:16")) << all(ds);
  text = deck_with_region("");
  text.resize(text.rfind("end\n"));  // drop `end sierra`
  ds = errors_of(text);
  EXPECT_TRUE(has_error(ds, 1, "'begin sierra s' at d.i:1 has no matching 'end'")) << all(ds);
}

TEST(Parser, MisplacedAndUnknownBlocksSkipTheirContents) {
  const auto ds = errors_of(deck_with_region("      begin materail\n        nonsense = 1\n        begin x\n"
                                              "        end\n      end\n"));
  ASSERT_EQ(ds.size(), 1u) << all(ds);
  EXPECT_EQ(ds[0].where.line, 34);
}

TEST(Parser, AMisspeltBlockIsReportedOnceNotAgainWhereItIsUsed) {
  std::string text = deck_with_region("");
  text.replace(text.find("begin solid section s\n"), 22, "begin solid sectoin s\n");
  const auto ds = errors_of(text);
  ASSERT_EQ(ds.size(), 1u) << all(ds);
  EXPECT_NE(ds[0].message.find("did you mean 'begin solid section'"), std::string::npos);
}

TEST(Parser, HostileInputIsBounded) {
  std::string text = "begin sierra s\n";
  for (int i = 0; i < 2000; ++i) text += "  nonsense = " + std::to_string(i) + "\n";
  text += "end\n";
  const auto ds = errors_of(text);
  EXPECT_LE(ds.size(), 51u);
  EXPECT_NE(ds.back().message.find("further errors not shown"), std::string::npos);
  std::string deep;
  for (int i = 0; i < 10000; ++i) deep += "begin sierra s\n";
  EXPECT_FALSE(errors_of(deep).empty());
}

}  // namespace

namespace {

// The mesh source from `database name` / `database type` (Exodus II by the extension), and the
// results `format`.
Deck deck_with_database(const std::string& lines) {
  return parse_deck_string(
      "begin sierra s\n  begin property specification for material m\n    density = 1\n"
      "    begin parameters for model elastic\n      youngs modulus = 1\n      poissons ratio = 0\n    end\n  end\n"
      "  begin solid section s\n  end\n  begin finite element model fem\n" + lines +
          "    begin parameters for block b\n      material = m\n      section = s\n    end\n  end\n"
          "  begin presto procedure p\n    begin time control\n      termination time = 1\n    end\n"
          "    begin presto region r\n      use finite element model fem\n"
          "      begin results output o\n        step increment = 1\n        format = both\n      end\n"
          "    end\n  end\nend\n",
      "/decks/d.i");
}

TEST(Parser, DatabaseTypeFollowsTheExtension) {
  using S = FiniteElementModelSpec::Source;
  for (const char* name : {"m.exo", "m.e", "m.g", "m.gen", "M.EXO", "sub/m.G"}) {
    const Deck d = deck_with_database(std::string("    database name = ") + name + "\n");
    EXPECT_EQ(d.models.at(0).source, S::exodus) << name;
  }
  EXPECT_EQ(deck_with_database("    database name = m.msh\n").models.at(0).source, S::gmsh);
  EXPECT_EQ(deck_with_database("    database name = m.exo\n    database type = gmsh\n").models.at(0).source, S::gmsh);
  const Deck d = deck_with_database("    database name = m.mesh\n    database type = exodus\n");
  EXPECT_EQ(d.models.at(0).source, S::exodus);
  EXPECT_EQ(d.models.at(0).database_path, "/decks/m.mesh");
  EXPECT_TRUE(d.procedure.region.results->xdmf);
  EXPECT_TRUE(d.procedure.region.results->exodus);
  EXPECT_NE(d.resolved_text.find("format = both"), std::string::npos);
}

TEST(Parser, ResultsFormatDefaultsToXdmf) {
  const Deck d = parse_deck_string(deck_with_region(
                                       "      begin results output o\n        step increment = 1\n      end\n"),
                                   "d.i");
  EXPECT_TRUE(d.procedure.region.results->xdmf);
  EXPECT_FALSE(d.procedure.region.results->exodus);
  const Deck e = parse_deck_string(deck_with_region("      begin results output o\n        step increment = 1\n"
                                                    "        format = exodus\n      end\n"),
                                   "d.i");
  EXPECT_FALSE(e.procedure.region.results->xdmf);
  EXPECT_TRUE(e.procedure.region.results->exodus);
}

}  // namespace
