// SPDX-License-Identifier: MIT
// Decks built in code for solver unit tests (no parser involved): one generated box, one material.
#pragma once

#include "inputs/deck.hpp"

namespace tribex::test {

inline inputs::Deck box_deck(int n, double size, inputs::MaterialModel model, inputs::ElementFormulation formulation,
                             double E = 200e9, double nu = 0.3, double rho = 7800.0) {
  inputs::Deck deck;
  deck.name = "test";
  deck.path = "test.i";
  inputs::MaterialSpec mat;
  mat.name = "m";
  mat.density = rho;
  mat.models.push_back({model, E, nu, {}});
  deck.materials.push_back(mat);
  inputs::SectionSpec section;
  section.name = "s";
  section.formulation = formulation;
  deck.sections.push_back(section);
  inputs::FiniteElementModelSpec fem;
  fem.name = "fem";
  inputs::GeneratedBoxSpec box;
  box.block_name = "b";
  box.size = {size, size, size};
  box.intervals = {n, n, n};
  fem.boxes.push_back(box);
  fem.blocks.push_back({"b", "m", model, "s", {}});
  deck.models.push_back(fem);
  deck.procedure.time_control.termination_time = 1.0;
  deck.procedure.region.finite_element_model = "fem";
  return deck;
}

}  // namespace tribex::test
