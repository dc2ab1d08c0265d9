// SPDX-License-Identifier: MIT
// Structured hex8 box generator.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/generated_plan.hpp"
#include "mesh/mesh.hpp"

namespace tribex::mesh {

struct BoxSpec {
  std::string name = "block";                   // the block; sets are NAME_xmin ... NAME_zmax
  std::array<double, 3> origin{0.0, 0.0, 0.0};  // m
  std::array<double, 3> size{1.0, 1.0, 1.0};    // m
  std::array<int, 3> intervals{1, 1, 1};
  /// Geometric grading: elements shrink toward this face ("xmin".."zmax"); each element is
  /// `grading_ratio` (>= 1) times its neighbour nearer that face. Empty: uniform (ratio must be 1).
  std::string grade_toward;
  double grading_ratio = 1.0;
};

/// One block NAME; node sets and side sets NAME_xmin, NAME_xmax, NAME_ymin, NAME_ymax,
/// NAME_zmin, NAME_zmax; node set NAME_all. Elements are numbered x fastest, then y, then z.
/// Throws MeshError for a bad spec (intervals < 1, size <= 0, unknown face, ratio < 1).
Mesh generate_box(const BoxSpec& spec);
/// The same box added to `into` in place, as append(into, generate_box(spec)) would, without the
/// copy: its nodes and elements numbered after those already there (reserve room beforehand and a
/// large box is written once; rank 0's peak memory in a parallel set-up). A block or set name
/// already in `into` is an error (MeshError), as for append.
void add_box(Mesh& into, const BoxSpec& spec);
/// Nodes and elements of the box of `spec` (for reserving room), or zeros for a bad spec.
std::array<long long, 2> box_size(const BoxSpec& spec);

/// The structured grid behind generate_box: nodes on the tensor product of three strictly
/// increasing coordinate lists (m), one block NAME and the same sets. Generators that map a grid
/// (the asperity's spherical tip, AFM surfaces) start from it.
Mesh generate_grid(const std::string& name, const std::array<std::vector<double>, 3>& axes);

/// The plans (generated_plan.hpp) of generate_box and generate_grid: the same numbers, sets and
/// coordinates, and the same MeshError for a bad spec, with no volume built.
GeneratedPlan plan_box(const BoxSpec& spec);
GeneratedPlan plan_grid(const std::string& name, const std::array<std::vector<double>, 3>& axes);

}  // namespace tribex::mesh
