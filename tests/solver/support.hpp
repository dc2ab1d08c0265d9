// SPDX-License-Identifier: MIT
// Decks built in code for solver unit tests (no parser involved): one generated box, one material; one
// contact interaction.
#pragma once

#include <string>

#include "inputs/cube_deck.hpp"
#include "inputs/deck.hpp"

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

// One frictionless node-to-face interaction "press": surface `slave` on side set `slave_set`, surface `master`
// on `master_set`.
inline inputs::ContactSpec one_contact(const std::string& slave, const std::string& slave_set, const std::string& master,
                                       const std::string& master_set) {
  inputs::ContactSpec spec;
  spec.surfaces.push_back({slave, {slave_set}, {}});
  spec.surfaces.push_back({master, {master_set}, {}});
  inputs::InteractionSpec it;
  it.name = "press";
  it.slave = slave;
  it.master = master;
  spec.interactions.push_back(it);
  return spec;
}

}  // namespace tribex::test
