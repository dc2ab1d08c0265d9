// SPDX-License-Identifier: MIT
// The smallest vertical distance between two surfaces of a mesh, each given as a side set whose
// faces are a height field seen from above (the tip's bottom face over an AFM surface's top).
#pragma once

#include <optional>
#include <string>

#include "mesh/mesh.hpp"

namespace tribex::mesh {

/// min (z_upper - z_lower) over every node of either side set that lies above or below a face of
/// the other: each node's height is compared with the other surface's height at the node's x, y
/// (faces split into the triangles 0-1-2 and 0-2-3, linear inside, as the contact search sees the
/// faceted surface). Covering both sets' nodes catches a tip node over a surface valley and a surface
/// peak under the tip. Negative where the surfaces interpenetrate; nullopt when no node of either set
/// lies over a face of the other. MeshError if a side set is missing.
std::optional<double> smallest_vertical_gap(const Mesh& mesh, const std::string& upper, const std::string& lower);

}  // namespace tribex::mesh
