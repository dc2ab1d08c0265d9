// SPDX-License-Identifier: MIT
// `begin afm surface` in the deck: values, defaults, the path relative to the deck, conflicts, and
// build_mesh making the same mesh as the generator called directly.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "inputs/diagnostics.hpp"
#include "mesh/afm/afm_mesh.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"

using namespace tribex;

namespace {

const std::string deck_path = std::string(TRIBEX_SOURCE_DIR) + "/tests/afm_mesh/afm_track.i";

std::string read(const std::string& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

std::string first_error(const std::string& text) {
  try {
    inputs::parse_deck_string(text, deck_path);
  } catch (const inputs::DeckError& e) {
    return e.diagnostics().front().str();
  }
  return "parsed";
}

}  // namespace

TEST(AfmDeck, ValuesDefaultsAndThePathRelativeToTheDeck) {
  const inputs::Deck deck = inputs::parse_deck_file(deck_path);
  ASSERT_EQ(deck.models.size(), 1u);
  const auto& a = deck.models[0].afm_surface;
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->channel, 0);
  ASSERT_TRUE(a->window && a->track);
  EXPECT_NEAR((*a->window)[0], 200e-9, 1e-21);
  EXPECT_NEAR((*a->window)[3], 30e-9, 1e-21);
  EXPECT_NEAR((*a->track)[2], 10e-9, 1e-21);
  EXPECT_NEAR(a->element_size, 0.5e-9, 1e-24);
  EXPECT_NEAR(a->depth, 20e-9, 1e-22);
  EXPECT_NEAR(a->coating_thickness, 2e-9, 1e-22);
  EXPECT_EQ(a->coating_layers, 4);
  EXPECT_NEAR(a->grading_ratio, 1.3, 1e-15);
  EXPECT_NE(a->file.find("inputs/data/afm/di-1.di"), std::string::npos) << a->file;
  EXPECT_TRUE(std::ifstream(a->file).good()) << a->file;
  // The resolved text (log.txt) carries the block in SI and parses back to the same values.
  EXPECT_NE(deck.resolved_text.find("element size = 5e-10"), std::string::npos) << deck.resolved_text;
  const auto again = inputs::parse_deck_string(deck.resolved_text, deck_path);
  EXPECT_EQ(again.models[0].afm_surface->window, a->window);
  EXPECT_EQ(again.models[0].afm_surface->depth, a->depth);

  // Defaults: no channel, window or track; element size 0.5 nm, no coating, 6 layers, ratio 1.3.
  std::string text = read(deck_path);
  for (const char* line : {"      channel = 0\n", "      window = 200 200 20 30 nm\n", "      track = 205 200 10 30 nm\n",
                           "      element size = 0.5 nm\n", "      coating thickness = 2 nm\n", "      coating layers = 4\n",
                           "      grading ratio = 1.3\n"})
    text = replace(text, line, "");
  const auto d = inputs::parse_deck_string(text, deck_path);
  const auto& b = *d.models[0].afm_surface;
  EXPECT_EQ(b.channel, -1);
  EXPECT_FALSE(b.window || b.track);
  EXPECT_EQ(b.element_size, 0.5e-9);
  EXPECT_EQ(b.coating_thickness, 0.0);
  EXPECT_EQ(b.coating_layers, 6);
  EXPECT_EQ(b.grading_ratio, 1.3);
}

TEST(AfmDeck, BadValuesAndConflictsNameTheLine) {
  const std::string text = read(deck_path);
  EXPECT_NE(first_error(replace(text, "grading ratio = 1.3", "grading ratio = 1.6")).find("afm_track.i:47:"), std::string::npos);
  EXPECT_NE(first_error(replace(text, "      depth = 20 nm\n", "")).find("depth"), std::string::npos);
  EXPECT_NE(first_error(replace(text, "window = 200 200 20 30 nm", "window = 200 200 20 nm")).find("afm_track.i:41:"),
            std::string::npos);
  const std::string both = first_error(replace(text, "    begin afm surface\n", "    database name = x.msh\n    begin afm surface\n"));
  EXPECT_NE(both.find("both 'database name' and a generated mesh"), std::string::npos) << both;
}

TEST(AfmDeck, BuildMeshMakesTheGeneratorsMesh) {
  const inputs::Deck deck = inputs::parse_deck_file(deck_path);
  const mesh::Mesh m = solver::build_mesh(deck.models[0]);
  mesh::afm::AfmMeshSpec s;
  const auto& a = *deck.models[0].afm_surface;
  s.window = a.window;
  s.track = a.track;
  s.depth = a.depth;
  s.coating_thickness = a.coating_thickness;
  s.coating_layers = a.coating_layers;
  const mesh::Mesh direct = mesh::afm::mesh_afm_file(a.file, a.channel, s);
  EXPECT_EQ(m.coordinates, direct.coordinates);
  EXPECT_EQ(m.connectivity, direct.connectivity);
  ASSERT_NE(m.find_block("coating"), nullptr);

  auto missing = deck.models[0];
  missing.afm_surface->file += ".missing";
  try {
    solver::build_mesh(missing);
    FAIL() << "no error for a missing map";
  } catch (const solver::SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("afm_track.i:38:5: error: 'begin afm surface'"), std::string::npos) << e.what();
  }
}
