// SPDX-License-Identifier: MIT
// Pre-processing of height maps before statistics (the report's Section 4.3 procedure):
// mean-plane levelling, cropping a window in physical units, resampling onto a finer grid,
// 3x3 median filter and light 3x3 weighted smoothing. All functions return a new map.
#pragma once

#include "mesh/afm/height_map.hpp"

namespace tribex::mesh::afm {

/// Subtracts the least-squares plane z = a + b x + c y (so the map has zero mean and no tilt).
HeightMap level_plane(const HeightMap& map);

/// Subtracts the mean height only.
HeightMap remove_mean(const HeightMap& map);

/// Keeps the pixels whose centres lie in [x0, x0+wx) x [y0, y0+wy) (metres, origin at pixel (0,0)).
/// Throws MeshError if the window is empty or leaves the map.
HeightMap crop(const HeightMap& map, double x0, double y0, double wx, double wy);

/// Bilinear resampling onto nx x ny pixels covering the same area (used to "expand to 1024 x 1024").
HeightMap resample(const HeightMap& map, std::size_t nx, std::size_t ny);

/// 3x3 median filter (edges use the available neighbours): removes isolated spikes.
HeightMap median_filter(const HeightMap& map);

/// 3x3 weighted average with weights [1 2 1]^T [1 2 1] / 16 (edges renormalised): light smoothing.
HeightMap smooth(const HeightMap& map);

/// Root-mean-square height about the mean, m.
double rms(const HeightMap& map);

}  // namespace tribex::mesh::afm
