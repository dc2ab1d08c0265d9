// SPDX-License-Identifier: MIT
// Decks built in code for solver unit tests (no parser involved): one generated box, one material.
#pragma once

#include "inputs/cube_deck.hpp"

namespace tribex::test {

// The n x n x n cube of edge `size`, block "b" (node and side sets b_xmin ... b_zmax), material "m".
inline inputs::Deck box_deck(int n, double size, inputs::MaterialModel model, inputs::ElementFormulation formulation,
                             double E = 200e9, double nu = 0.3, double rho = 7800.0) {
  return inputs::cube_deck({.intervals = n,
                            .size = size,
                            .model = model,
                            .formulation = formulation,
                            .youngs_modulus = E,
                            .poissons_ratio = nu,
                            .density = rho});
}

}  // namespace tribex::test
