// SPDX-License-Identifier: MIT
// A deck built in code, without the parser: one generated cube of hex8 elements, one material with
// one model, one section. The solver unit tests (tests/solver/support.hpp) and `tribex bench`
// start from it and add their loads, boundary conditions and time control.
#pragma once

#include <string>

#include "inputs/deck.hpp"

namespace tribex::inputs {

struct CubeDeckSpec {
  std::string name = "test";  // the deck's name
  std::string path = "test.i";  // stands for the deck file in messages
  std::string finite_element_model = "fem";
  std::string block = "b";  // also the generated box: node and side sets b_xmin ... b_zmax, b_all
  std::string material = "m";
  std::string section = "s";
  int intervals = 1;  // elements per edge
  double size = 1.0;  // edge length, m
  MaterialModel model = "elastic";
  ElementFormulation formulation = ElementFormulation::mean_quadrature;
  double youngs_modulus = 200e9;  // Pa
  double poissons_ratio = 0.3;
  double density = 7800.0;  // kg/m^3
};

/// The deck of `spec`, termination time 1 s, every other procedure setting at its default.
Deck cube_deck(const CubeDeckSpec& spec);

}  // namespace tribex::inputs
