// SPDX-License-Identifier: MIT
// Format detection by content, shared file reading and the final sanity check of every reader.
#include <cmath>
#include <fstream>
#include <sstream>

#include "mesh/afm/height_map.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {

std::string read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path + ": cannot open the file (check the path and permissions)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void check_height_map(const HeightMap& map, const std::string& where) {
  if (map.nx < 2 || map.ny < 2)
    throw MeshError(where + ": expected at least 2 x 2 pixels, got " + std::to_string(map.nx) + " x " +
                    std::to_string(map.ny) + " (the file holds no usable image)");
  if (!(std::isfinite(map.dx) && map.dx > 0.0 && std::isfinite(map.dy) && map.dy > 0.0))
    throw MeshError(where + ": expected finite positive pixel sizes, got dx = " + std::to_string(map.dx) +
                    " m, dy = " + std::to_string(map.dy) + " m (fix the scan size in the header)");
  if (map.heights.size() != map.nx * map.ny)
    throw MeshError(where + ": expected " + std::to_string(map.nx * map.ny) + " heights, got " +
                    std::to_string(map.heights.size()));
  for (std::size_t i = 0; i < map.heights.size(); ++i) {
    if (!std::isfinite(map.heights[i]))
      throw MeshError(where + ": height at pixel (" + std::to_string(i % map.nx) + ", " +
                      std::to_string(i / map.nx) + ") is not a finite number (NaN or Inf in the data)");
    if (std::fabs(map.heights[i]) > 1.0)
      throw MeshError(where + ": height " + std::to_string(map.heights[i]) + " m at pixel (" + std::to_string(i % map.nx) +
                      ", " + std::to_string(i / map.nx) + ") is absurd for a topography map (check the Z scale and units)");
  }
  if (map.size_x() > 1.0 || map.size_y() > 1.0)
    throw MeshError(where + ": scan size " + std::to_string(map.size_x()) + " m x " + std::to_string(map.size_y()) +
                    " m is absurd for an AFM map (check the lateral units)");
}

HeightMap read_height_map(const std::string& path, int channel) {
  std::string head;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw MeshError(path + ": cannot open the file (check the path and permissions)");
    head.resize(64);
    in.read(head.data(), 64);
    head.resize(static_cast<std::size_t>(in.gcount()));
  }
  if (head.rfind("\\*File list", 0) == 0 || head.rfind("\\*File List", 0) == 0)
    return read_nanoscope(path, channel);
  if (channel > 0)
    throw MeshError(path + ": only Nanoscope files have several channels; --channel " + std::to_string(channel) +
                    " does not apply (use channel 0 or leave it out)");
  if (head.rfind("Gwyddion Simple Field 1.0", 0) == 0) return read_gsf(path);
  if (!head.empty() && head[0] == '#' && head.find("Channel") != std::string::npos) return read_gwyddion_matrix(path);
  if (!head.empty() && head[0] == '#' && (head.find("Width") != std::string::npos)) return read_gwyddion_matrix(path);
  return read_xyz_text(path);
}

}  // namespace tribex::mesh::afm
