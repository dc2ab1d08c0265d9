// SPDX-License-Identifier: MIT
#include "inputs/cube_deck.hpp"

namespace tribex::inputs {

Deck cube_deck(const CubeDeckSpec& spec) {
  Deck deck;
  deck.name = spec.name;
  deck.path = spec.path;
  MaterialSpec material;
  material.name = spec.material;
  material.density = spec.density;
  material.models.push_back({spec.model, spec.youngs_modulus, spec.poissons_ratio, {}, {}});
  deck.materials.push_back(material);
  SectionSpec section;
  section.name = spec.section;
  section.formulation = spec.formulation;
  deck.sections.push_back(section);
  FiniteElementModelSpec fem;
  fem.name = spec.finite_element_model;
  GeneratedBoxSpec box;
  box.block_name = spec.block;
  box.size = {spec.size, spec.size, spec.size};
  box.intervals = {spec.intervals, spec.intervals, spec.intervals};
  fem.boxes.push_back(box);
  fem.blocks.push_back({spec.block, spec.material, spec.model, spec.section, {}});
  deck.models.push_back(fem);
  deck.procedure.time_control.termination_time = 1.0;
  deck.procedure.region.finite_element_model = spec.finite_element_model;
  return deck;
}

}  // namespace tribex::inputs
