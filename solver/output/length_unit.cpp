// SPDX-License-Identifier: MIT
#include "solver/output/length_unit.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tribex::solver::output {

LengthUnit length_unit_named(const std::string& name) {
  if (name == "m") return {"m", 1.0};
  if (name == "um") return {"um", 1e6};
  if (name == "nm") return {"nm", 1e9};
  throw std::invalid_argument("length unit '" + name + "': expected m, um or nm");
}

LengthUnit resolve_length_unit(const std::string& choice, const mesh::Mesh& mesh) {
  return resolve_length_unit(choice, mesh::bounding_box(mesh));
}

LengthUnit resolve_length_unit(const std::string& choice, const mesh::BoundingBox& box) {
  if (choice != "auto") return length_unit_named(choice);
  const auto& [lo, hi] = box;
  double extent = 0.0;  // an empty mesh stays in metres
  for (int k = 0; k < 3; ++k)
    if (hi[k] >= lo[k]) extent = std::max(extent, hi[k] - lo[k]);
  if (extent > 0.0 && extent < 1e-6) return length_unit_named("nm");
  if (extent > 0.0 && extent < 1e-3) return length_unit_named("um");
  return length_unit_named("m");
}

}  // namespace tribex::solver::output
