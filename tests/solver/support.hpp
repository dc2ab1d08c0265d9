// SPDX-License-Identifier: MIT
// Decks built in code for solver unit tests (no parser involved): one generated box, one material.
#pragma once

#include "inputs/cube_deck.hpp"

namespace tribex::test {

// The n x n x n cube of edge `size`, block "b" (node and side sets b_xmin ... b_zmax), material "m".
inline inputs::Deck box_deck(int n, double size, inputs::MaterialModel model, inputs::ElementFormulation formulation,
                             double E = 200e9, double nu = 0.3, double rho = 7800.0) {
  inputs::CubeDeckSpec spec;
  spec.intervals = n;
  spec.size = size;
  spec.model = model;
  spec.formulation = formulation;
  spec.youngs_modulus = E;
  spec.poissons_ratio = nu;
  spec.density = rho;
  return inputs::cube_deck(spec);
}

}  // namespace tribex::test
