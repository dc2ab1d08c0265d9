// SPDX-License-Identifier: MIT
// An all-hex8 substrate block whose top follows an AFM height map (issue 5, scope item 3): the
// bicubic-spline surface of the map (cubic_spline.hpp), a structured grid with elements of at
// most `element_size` in the track, graded (ratio <= 1.3) away from it in x and y and with depth,
// and an optional bonded coating of its own block. Route 1 of docs/dependencies.md section 3: the grid
// is built here and written with mesh::write_gmsh (gmsh discrete entities).
//
// Geometry (mesh coordinates = map coordinates, pixel (ix, iy) centred at ((ix+1/2) dx, (iy+1/2) dy)):
//   top      z = s(x, y), the spline surface of the levelled map: the measured, outer surface;
//   coating  s - t_c <= z <= s (thickness measured along z), coating_layers equal layers;
//   bottom   z = z_ref - depth, z_ref = mean height of the map pixels inside the window;
//   between  substrate layers blended from the flat bottom to s - t_c (node k at
//            z_bot + (s - t_c - z_bot) sigma_k), first layer <= element_size, then graded.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "mesh/afm/height_map.hpp"
#include "mesh/mesh.hpp"

namespace tribex::mesh::afm {

/// The smallest window, in pixel spacings per side, that `generate_afm_mesh` meshes (MeshError below)
/// unless `AfmMeshSpec::interpolate_small_window`.
inline constexpr int min_window_pixels = 4;

struct AfmMeshSpec {
  /// x0, y0, width, height (m) in map coordinates; unset: the whole map.
  std::optional<std::array<double, 4>> window;
  /// The contact track (m), inside the window; unset: the whole window.
  std::optional<std::array<double, 4>> track;
  double element_size = 0.5e-9;     // m, largest element edge in the track (x, y and the top layer)
  double depth = 50e-9;             // m, from the window's mean height to the flat bottom
  double coating_thickness = 0.0;   // m, 0: no coating
  int coating_layers = 6;           // elements through the coating
  double grading_ratio = 1.3;       // in [1, 1.3]: size ratio of neighbouring elements outside the track
  bool interpolate_small_window = false;  // mesh a window under min_window_pixels a side (the spline between pixels)
  long max_elements = 20'000'000;   // refuse a larger mesh before allocating it (~ 6 GB of mesh + solver state)
};

/// What was built, for the command line and the tests.
struct AfmMeshReport {
  int nx = 0, ny = 0;                 // elements along x and y
  int substrate_layers = 0, coating_layers = 0;
  double track_element_size = 0.0;    // m, largest element edge in the track's top layer
  double min_scaled_jacobian = 0.0;   // over all elements
  double mean_scaled_jacobian = 0.0;
  double min_scaled_jacobian_track = 0.0;  // over the elements under the track (all layers)
  double z_reference = 0.0, z_bottom = 0.0;  // m
  double surface_rms = 0.0;           // m, RMS of the map pixels in the window about their mean
  std::array<double, 4> window{}, track{};  // m, as used
};

/// Builds the block on an already levelled map. Blocks `substrate` (and `coating`); side sets and
/// node sets `substrate_top` (the contact surface: the coating's top when there is a coating),
/// `substrate_track` (the part of it over the track), `substrate_bottom`, `substrate_sides` and
/// `substrate_xmin`, `_xmax`, `_ymin`, `_ymax` (coating sides included), all outward.
/// Throws MeshError (naming map.source) for a bad spec or a mesh that would invert; the result
/// has passed mesh::validate.
Mesh generate_afm_mesh(const HeightMap& map, const AfmMeshSpec& spec, AfmMeshReport* report = nullptr);

/// read_height_map(path, channel), least-squares plane levelling of the whole map, generate_afm_mesh.
Mesh mesh_afm_file(const std::string& path, int channel, const AfmMeshSpec& spec, AfmMeshReport* report = nullptr);

}  // namespace tribex::mesh::afm
