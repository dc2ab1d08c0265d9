// SPDX-License-Identifier: MIT
// gmsh .msh (format 4.1) read and write through the gmsh C++ API.
//
// Mapping: 3-D physical groups -> element blocks (hex8 only); 2-D physical groups -> side sets
// (each quad matched to the hex face it lies on) and node sets of the same name;
// 0-D/1-D physical groups -> node sets. A file with no 3-D physical group gives one block
// "block_1" of all hexes. Unnamed physical groups are named "block_<tag>",
// "surface_<tag>", "nodes_<tag>".
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace tribex::mesh {

/// Throws MeshError (file name, what is wrong, the fix) for a missing/unreadable file, non-hex
/// volume elements, quads that are not faces of the volume mesh, or an invalid mesh.
Mesh read_gmsh(const std::string& path);

/// Writes blocks as 3-D physical groups, side sets as 2-D physical groups (quads), node sets
/// that are not the node set of a side set as 0-D physical groups. MSH 4.1, binary (`binary` false: ASCII;
/// `version` 2.2: the older format; both for the tests of the readers).
void write_gmsh(const Mesh& mesh, const std::string& path, bool binary = true, double version = 4.1);

}  // namespace tribex::mesh
