// SPDX-License-Identifier: MIT
// The length unit of results.h5/.xdmf: coordinates and every length field (displacement) are
// written in it so that ParaView gets numbers near 1 (at SI coordinates of ~1e-8 m its renderer's
// depth range collapses and pictures turn to noise, issue 27). Every other field stays SI.
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace tribex::solver::output {

struct LengthUnit {
  std::string name = "m";  // "m", "um" or "nm" (ASCII: it goes into XML and HDF5 attributes)
  double per_metre = 1.0;  // value in this unit = value in metres x per_metre
};

/// "m", "um" or "nm"; throws std::invalid_argument for anything else.
LengthUnit length_unit_named(const std::string& name);

/// The deck's `length unit` choice: "auto" is nm for a model whose largest bounding-box extent is
/// under 1 um, um under 1 mm, else m; any other choice is length_unit_named.
LengthUnit resolve_length_unit(const std::string& choice, const mesh::BoundingBox& box);
LengthUnit resolve_length_unit(const std::string& choice, const mesh::Mesh& mesh);

}  // namespace tribex::solver::output
