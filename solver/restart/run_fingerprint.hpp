// SPDX-License-Identifier: MIT
// What a restart file records of the run that wrote it: the resolved deck (text, as integer codes)
// and the SHA-256 of the mesh (coordinates and connectivity). A resumed run compares them with its own.
#pragma once

#include <string>
#include <vector>

#include "mesh/exodus_slices.hpp"
#include "mesh/generated_plan.hpp"
#include "mesh/mesh.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {

/// Text as integer codes (a restart archive holds numbers only), and back.
std::vector<long long> as_codes(const std::string& text);
std::string from_codes(const std::vector<long long>& codes);
/// SHA-256 (hex) of the mesh's coordinates and connectivity bytes.
std::string mesh_sha256(const mesh::Mesh& m);
/// mesh_sha256 of the plan's mesh (mesh/generated_plan.hpp), the arrays generated and hashed 65,536
/// nodes and elements at a time: the same digest without the whole mesh in memory.
std::string mesh_sha256(const mesh::GeneratedPlan& plan);
/// The same of an Exodus or MSH 4.1 file read in slices (mesh/mesh_slices.hpp), 65,536 nodes and elements at a time:
/// read_exodus's (read_gmsh's) mesh's digest (the nodes no element uses dropped and the others renumbered, as it does, with a
/// bit per node of the file: two passes over the connectivity, one over the coordinates).
std::string mesh_sha256(const mesh::MeshSlices& file);
/// "" when the restart file was written by this deck and mesh (or by a tribex that did not record
/// them); else what differs, one line.
std::string restart_difference(const StateArchive& archive, const std::string& deck_text, const std::string& mesh_hash);

}  // namespace tribex::solver
