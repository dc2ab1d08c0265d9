// SPDX-License-Identifier: MIT
// The size limits of the asperity generator (mesh/README.md, "Asperity generator limits"), all
// checked at once: every violated limit is one line naming the deck key, the limit's formula with
// its numbers, and the nearest valid value. The suggestions are consistent: a limit that depends
// on another key (tip height on tip width, fine half width on tip width) is computed with that
// key's suggested value when it is itself out of bounds, so a deck with every suggestion applied
// meshes.
#pragma once

#include <string>
#include <vector>

#include "mesh/asperity.hpp"

namespace tribex::mesh {

struct AsperityLimitViolation {
  std::string key;      // the deck key of `begin generated asperity` ("tip width")
  std::string message;  // one line: the limit, the value, the nearest valid value
};

/// Every violated limit of `spec`, in key order (empty: it meshes).
std::vector<AsperityLimitViolation> asperity_limit_violations(const AsperitySpec& spec);

/// The column's sag: height of the tip's bottom face at the column corner (r = w/sqrt(2)) above
/// the apex, m: R - sqrt(R^2 - w^2/2) for the sphere, w^2/(4R) for the paraboloid.
double asperity_corner_sag(const AsperitySpec& spec, double tip_width);

}  // namespace tribex::mesh
