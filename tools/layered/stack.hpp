// SPDX-License-Identifier: MIT
// An elastic layer stack: layers bonded to each other and to an elastic half-space or a rigid base
// (docs/theory.md 11.4). SI units throughout.
#pragma once

#include <optional>
#include <vector>

namespace tribex::layered {

struct Elastic {
  double youngs = 0.0;   // Pa
  double poisson = 0.0;  // -
  double shear() const { return youngs / (2.0 * (1.0 + poisson)); }
  /// Plane-strain modulus E* = E/(1 - nu^2) (the report's Ebar); infinite E gives infinity.
  double plane_strain() const { return youngs / (1.0 - poisson * poisson); }
};

struct Layer {
  double thickness = 0.0;  // m
  Elastic material;
};

/// Layers from the surface down, then the base: an elastic half-space, or rigid when `substrate`
/// is empty.
struct Stack {
  std::vector<Layer> layers;
  std::optional<Elastic> substrate;

  double total_thickness() const {
    double t = 0.0;
    for (const auto& l : layers) t += l.thickness;
    return t;
  }
  /// The top layer's material (the substrate's when there is no layer).
  const Elastic& top() const { return layers.empty() ? *substrate : layers.front().material; }
};

/// Throws tools::BadInput naming the offending value and the fix (thickness > 0, E > 0,
/// -1 < nu < 0.5, at least a layer or a substrate).
void validate(const Stack& stack);

}  // namespace tribex::layered
