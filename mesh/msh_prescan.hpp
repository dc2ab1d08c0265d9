// SPDX-License-Identifier: MIT
// Structural check of an MSH 4.1 file (ASCII or binary) before gmsh parses it.
//
// gmsh 4.8's reader trusts the counts and tags in $Nodes and $Elements: a corrupt (not merely
// truncated) file can make it crash or spend minutes allocating for a huge tag. This walks both
// sections with bounds checks and verifies every node and element tag lies in the range the section
// header declares, every element type is known, and the sections end where their counts say.
// Files in other versions (2.2) are left to gmsh.
#pragma once

#include <string>

namespace tribex::mesh {

/// Throws MeshError "PATH: byte OFFSET: what is wrong; fix" on the first inconsistency.
/// `nodes_per_element(type)` returns the node count of a gmsh element type, or <= 0 if unknown.
void prescan_msh41(const std::string& path, int (*nodes_per_element)(int type));

}  // namespace tribex::mesh
