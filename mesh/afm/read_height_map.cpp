// SPDX-License-Identifier: MIT
// Format detection by content, shared file reading and the final sanity check of every reader.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "mesh/afm/height_map.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {

namespace {

namespace fs = std::filesystem;

// The largest AFM map file read (a 16384 x 16384 float32 map is 1 GiB); a header that claims more, or
// a device, is refused before anything is allocated.
constexpr std::uintmax_t max_map_file_bytes = std::uintmax_t(1) << 30;

// Only regular files (a FIFO would block, /dev/zero never ends) of a size an AFM map can have.
std::uintmax_t regular_file_size(const std::string& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw MeshError(path + ": cannot open the file (check the path and permissions)");
  if (!fs::is_regular_file(status))
    throw MeshError(path + ": not a regular file (a folder, device or pipe); give the path of an AFM map file");
  const auto size = fs::file_size(path, ec);
  if (ec) throw MeshError(path + ": cannot read the file size (" + ec.message() + ")");
  if (size > max_map_file_bytes)
    throw MeshError(path + ": the file is " + std::to_string(size) + " bytes, more than the " +
                    std::to_string(max_map_file_bytes >> 20) + " MiB an AFM map file may have here (crop the map first)");
  return size;
}

bool ends_with(std::string s, const std::string& suffix) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Nanoscope files are .spm, .di or numbered .000-.999.
bool nanoscope_extension(const std::string& path) {
  if (ends_with(path, ".spm") || ends_with(path, ".di")) return true;
  const std::string ext = fs::path(path).extension().string();
  return ext.size() == 4 && std::isdigit(static_cast<unsigned char>(ext[1])) &&
         std::isdigit(static_cast<unsigned char>(ext[2])) && std::isdigit(static_cast<unsigned char>(ext[3]));
}

}  // namespace

std::string read_file_bytes(const std::string& path) {
  const auto size = regular_file_size(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path + ": cannot open the file (check the path and permissions)");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

void check_height_map(const HeightMap& map, const std::string& where) {
  if (map.nx < 2 || map.ny < 2)
    throw MeshError(where + ": expected at least 2 x 2 pixels, got " + std::to_string(map.nx) + " x " +
                    std::to_string(map.ny) + " (the file holds no usable image)");
  if (!(std::isfinite(map.dx) && map.dx >= 1e-13 && std::isfinite(map.dy) && map.dy >= 1e-13))
    throw MeshError(where + ": expected finite pixel sizes of at least 0.1 pm, got dx = " + std::to_string(map.dx) +
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
  if (regular_file_size(path) == 0) throw MeshError(path + ": the file is empty");
  std::string head;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw MeshError(path + ": cannot open the file (check the path and permissions)");
    head.resize(64);
    in.read(head.data(), 64);
    head.resize(static_cast<std::size_t>(in.gcount()));
  }
  const bool nanoscope = head.rfind("\\*File list", 0) == 0 || head.rfind("\\*File List", 0) == 0;
  const bool gsf = head.rfind("Gwyddion Simple Field 1.0", 0) == 0;
  // The extension names the format the user means: say which one did not match instead of trying text.
  if (ends_with(path, ".gsf") && !gsf)
    throw MeshError(path + ":1:1: a .gsf file must start with 'Gwyddion Simple Field 1.0' (not a Gwyddion Simple "
                    "Field file; check the file or its extension)");
  if (nanoscope_extension(path) && !nanoscope)
    throw MeshError(path + ":1:1: a Nanoscope file (.spm, .di, .000-.999) must start with '\\*File list' (not a "
                    "Nanoscope file; check the file or its extension)");
  if (nanoscope) return read_nanoscope(path, channel);
  if (channel > 0)
    throw MeshError(path + ": only Nanoscope files have several channels; --channel " + std::to_string(channel) +
                    " does not apply (use channel 0 or leave it out)");
  if (gsf) return read_gsf(path);
  if (!head.empty() && head[0] == '#' && head.find("Channel") != std::string::npos) return read_gwyddion_matrix(path);
  if (!head.empty() && head[0] == '#' && (head.find("Width") != std::string::npos)) return read_gwyddion_matrix(path);
  return read_xyz_text(path);
}

}  // namespace tribex::mesh::afm
