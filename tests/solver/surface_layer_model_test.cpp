// SPDX-License-Identifier: MIT
// Mixed blocks in the model: `begin surface layer block` gives the skin its own section, the mass is
// that of the unsplit mesh, and the quasi-static guard's translation energy counts the skin with its
// parent as one body (not the nodes between them twice).
#include <gtest/gtest.h>

#include <cmath>

#include "solver/errors.hpp"
#include "solver/guards/block_translation.hpp"
#include "solver/model.hpp"
#include "support.hpp"

namespace tribex {
namespace {

inputs::Deck mixed_box(int layers) {
  auto deck = test::box_deck(4, 1e-8, "elastic", inputs::ElementFormulation::mean_quadrature);
  inputs::SectionSpec fi = deck.sections[0];
  fi.name = "fi";
  fi.formulation = inputs::ElementFormulation::fully_integrated;
  deck.sections.push_back(fi);
  auto& fem = deck.models[0];
  fem.surface_layers.push_back({"skin", "b", "b_zmax", layers, {}, {}, {}});
  auto skin = fem.blocks[0];
  skin.block = "skin";
  skin.section = "fi";
  fem.blocks.push_back(skin);
  return deck;
}

TEST(SurfaceLayerModel, SkinGetsItsOwnSectionAndTheMassIsUnchanged) {
  const solver::Model plain = solver::build_model(test::box_deck(4, 1e-8, "elastic", inputs::ElementFormulation::mean_quadrature));
  const solver::Model m = solver::build_model(mixed_box(2));
  ASSERT_EQ(m.blocks.size(), 2u);
  EXPECT_EQ(m.blocks[0].name, "b");
  EXPECT_EQ(m.blocks[0].count, 32);
  EXPECT_EQ(m.blocks[0].formulation, inputs::ElementFormulation::mean_quadrature);
  EXPECT_EQ(m.blocks[1].name, "skin");
  EXPECT_EQ(m.blocks[1].first_element, 32);
  EXPECT_EQ(m.blocks[1].count, 32);
  EXPECT_EQ(m.blocks[1].formulation, inputs::ElementFormulation::fully_integrated);
  for (int e = 0; e < 64; ++e) EXPECT_EQ(m.element_block[e], e < 32 ? 0 : 1);
  EXPECT_EQ(m.block_body, (std::vector<int>{0, 0}));
  // Same nodes, same elements (reordered): the lumped masses agree to round-off of the sum order.
  ASSERT_EQ(m.mass.size(), plain.mass.size());
  for (std::size_t n = 0; n < m.mass.size(); ++n) EXPECT_NEAR(m.mass[n], plain.mass[n], 1e-14 * plain.mass[n]);
  EXPECT_NEAR(m.total_mass, plain.total_mass, 1e-14 * plain.total_mass);
}

TEST(SurfaceLayerModel, TranslationEnergyCountsTheSkinWithItsParent) {
  const solver::Model m = solver::build_model(mixed_box(1));
  solver::BlockTranslation translation(m);
  // Every node at (1, 2, 3) m/s: the body's translation energy is its kinetic energy, M |v|^2 / 2.
  std::vector<double> v;
  for (int n = 0; n < m.mesh.node_count(); ++n) v.insert(v.end(), {1.0, 2.0, 3.0});
  EXPECT_NEAR(translation.kinetic_energy(v), 0.5 * m.total_mass * 14.0, 1e-12 * m.total_mass * 14.0);
}

TEST(SurfaceLayerModel, WholeBlockIsRefusedWithTheDeckLine) {
  auto deck = mixed_box(4);
  deck.models[0].surface_layers[0].where = {"deck.i", 7, 5};
  try {
    solver::build_model(deck);
    FAIL() << "no SetupError";
  } catch (const solver::SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.i:7:5: error: surface layer block: layers = 4 takes all 64 elements of block 'b'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tribex
