// SPDX-License-Identifier: MIT
// A topography height map read from an AFM/SPM file, in SI units, and the readers that make one.
//
// Layout: heights[iy * nx + ix] in metres; ix runs along the fast-scan direction (x), iy along the
// slow-scan direction (y). Pixel spacings dx, dy in metres; the map covers nx*dx by ny*dy.
// Every reader throws mesh::MeshError with "FILE: byte N" or "FILE:LINE", what was expected and the
// fix; no reader returns a half-filled map.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tribex::mesh::afm {

struct HeightMap {
  std::size_t nx = 0, ny = 0;   // pixel counts along x (fast scan) and y (slow scan)
  double dx = 0.0, dy = 0.0;    // pixel spacing, m
  std::vector<double> heights;  // [ny][nx] row-major, m
  std::string channel;          // channel name as the file calls it
  std::string source;           // file it came from

  double& at(std::size_t ix, std::size_t iy) { return heights[iy * nx + ix]; }
  double at(std::size_t ix, std::size_t iy) const { return heights[iy * nx + ix]; }
  double size_x() const { return static_cast<double>(nx) * dx; }
  double size_y() const { return static_cast<double>(ny) * dy; }
};

/// One image channel listed in a Nanoscope header.
struct ChannelInfo {
  std::string name;     // e.g. "ZSensor", "Height", "Phase"
  bool is_height;       // Z sensitivity has a length unit (nm/V, ~m/V)
};

/// Bruker / Digital Instruments Nanoscope (.spm, .000, .di): 16- and 32-bit channels.
/// `channel` < 0 picks the first height channel.
HeightMap read_nanoscope(const std::string& path, int channel = -1);
std::vector<ChannelInfo> nanoscope_channels(const std::string& path);

/// Gwyddion Simple Field 1.0 (.gsf): text header, NUL padding to a multiple of 4, float32 LE data.
HeightMap read_gsf(const std::string& path);

/// Gwyddion ASCII matrix export: '#' header (Width, Height, Value units) then rows of numbers (row = y).
HeightMap read_gwyddion_matrix(const std::string& path);

/// Plain XYZ text: one "x y z" triple per line on a regular grid, SI metres unless a leading comment
/// line "# units: nm" (or um, pm, m) says otherwise. '#' lines are comments.
HeightMap read_xyz_text(const std::string& path);

/// Picks the reader by content (Nanoscope "\*File list", GSF magic line, '#' matrix header) and
/// falls back to XYZ text. `channel` only applies to multi-channel formats (Nanoscope); others
/// accept -1 or 0.
HeightMap read_height_map(const std::string& path, int channel = -1);

/// Reads a whole regular file of at most 1 GiB into memory (MeshError otherwise: a device, pipe or folder,
/// a missing or unreadable file, a larger one).
std::string read_file_bytes(const std::string& path);

/// Throws MeshError unless the map is usable: >= 2x2 pixels, finite positive spacings and finite heights.
void check_height_map(const HeightMap& map, const std::string& where);

}  // namespace tribex::mesh::afm
