// SPDX-License-Identifier: MIT
#include "tools/layered/stack.hpp"

#include <cmath>
#include <string>

#include "tools/common/errors.hpp"

namespace tribex::layered {
namespace {

void check_material(const Elastic& m, const std::string& what) {
  if (!(m.youngs > 0) || !std::isfinite(m.youngs))
    throw tools::BadInput(what + ": Young's modulus must be > 0 and finite (e.g. 8GPa)");
  if (!(m.poisson > -1.0 && m.poisson < 0.5))
    throw tools::BadInput(what + ": Poisson's ratio must lie in (-1, 0.5) (an incompressible 0.5 is not supported; use 0.499)");
}

}  // namespace

void validate(const Stack& stack) {
  if (stack.layers.empty() && !stack.substrate)
    throw tools::BadInput("layer stack: give at least one layer or an elastic substrate");
  for (std::size_t i = 0; i < stack.layers.size(); ++i) {
    const std::string what = "layer " + std::to_string(i + 1);
    if (!(stack.layers[i].thickness > 0) || !std::isfinite(stack.layers[i].thickness))
      throw tools::BadInput(what + ": thickness must be > 0 (e.g. --thickness 2nm)");
    check_material(stack.layers[i].material, what);
  }
  if (stack.substrate) check_material(*stack.substrate, "substrate");
}

}  // namespace tribex::layered
