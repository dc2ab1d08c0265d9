// SPDX-License-Identifier: MIT
// The report's asperity problem (Fig. 3.2): a sphere-tipped asperity above a (optionally coated)
// substrate, all hex8, graded so the elements at the contact are as small as asked while the total
// stays small.
//
//            tip_top
//        +-----------+        block `tip`: a square column (side tip_width) whose bottom face
//        |           |        follows the sphere z = gap + R - sqrt(R^2 - x^2 - y^2) (tip_surface)
//         \_________/  <- apex at (0, 0, gap)
//   +-------------------------+  substrate_top (z = 0): top of block `coating` if coated, else `substrate`
//   |                         |  substrate_sides (x, y = +-substrate_width/2), substrate_bottom (z = -depth)
//   +-------------------------+
//
// In x and y the spacing is `element_size` within |x|, |y| <= fine_half_width and grows by
// `grading_ratio` per element beyond (the substrate in x: within fine_x_range when given); in z it is `element_size` within fine_depth of the contact
// and grows likewise. Node sets of the same names as the side sets, plus `tip_axis_top` (the tip
// top node on the axis) and `substrate_axis_bottom`.
//
// quarter = true meshes only x >= 0, y >= 0 (the problem is symmetric about x = 0 and y = 0): a
// quarter of the elements for the same resolution. The planes x = 0 and y = 0 are then node sets
// `symmetry_x` and `symmetry_y` (tip and substrate nodes; fix x resp. y there), the side sets
// `*_sides` hold only the outer faces x, y = +width/2, and every force and area the run reports is a
// quarter of the full problem's.
#pragma once

#include <array>
#include <optional>

#include "mesh/generated_plan.hpp"
#include "mesh/mesh.hpp"

namespace tribex::mesh {

struct AsperitySpec {
  double radius = 27e-9;            // R of the spherical tip, m
  double tip_width = 20e-9;         // side of the square tip column, m (corners must stay inside R)
  double tip_height = 15e-9;        // column height above the apex, m
  double substrate_width = 40e-9;   // side of the square substrate, m
  double substrate_depth = 20e-9;   // m
  double gap = 0.0;                 // apex height above the substrate top, m
  double element_size = 0.5e-9;     // at the contact, m
  double fine_half_width = 4e-9;    // uniformly fine region |x|, |y| <= this, m
  double fine_depth = 2e-9;         // uniformly fine layers above the apex and below the surface, m
  double grading_ratio = 1.25;      // growth per element outside the fine region
  double coating_thickness = 0.0;   // bonded coating on the substrate (block `coating`), m; 0: none
  int coating_layers = 6;           // elements through the coating
  bool quarter = false;             // mesh x >= 0, y >= 0 only (symmetry planes: node sets symmetry_x, symmetry_y)
  bool tip_only = false;            // no substrate block: the tip over another mesh's surface (e.g. an AFM one)
  // Shape of the tip's bottom face: the sphere z = R - sqrt(R^2 - r^2), or Hertz's paraboloid
  // z = r^2 / (2R) (the profile for which Hertz's solution is exact; verification/hertz/README.md).
  bool paraboloid = false;
  bool place_apex = false;          // translate the mesh so that the apex sits at `apex` (else at (0, 0, gap))
  std::array<double, 3> apex{};     // m; the substrate top, when there is one, is then at apex z - gap
  // The substrate's uniformly fine region along x, X0 <= 0 <= X1 from the apex axis (default: +-fine_half_width;
  // a quarter model uses X1 only): a strip as long as a slide, wider than the tip column allows.
  std::optional<std::array<double, 2>> fine_x_range;
};

/// Throws MeshError for inconsistent sizes: every violated limit, one line each with the nearest
/// valid value (asperity_limits.hpp).
Mesh generate_asperity(const AsperitySpec& spec);
/// Its plan (generated_plan.hpp): the same numbers, coordinates and sets, no volume built (the
/// volume's Jacobians are checked where the elements are built).
GeneratedPlan plan_asperity(const AsperitySpec& spec);

/// Node coordinates on [lo, hi] with spacing h in [lo, lo + fine] growing by `ratio` per element
/// after it (the last element absorbs the remainder); used by the asperity and AFM generators.
std::vector<double> graded_axis(double lo, double hi, double h, double fine, double ratio);

}  // namespace tribex::mesh
