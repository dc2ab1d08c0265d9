// SPDX-License-Identifier: MIT
// Where PSTD profiles come from, before oversampling: profile files (CSV/text) and height maps (AFM). A height
// map gives the substrate as one row (the scan direction) and counterface segments as pieces of columns
// (orthogonal to the scan direction), as in the report. Positions and heights are SI.
//
// The only height-map format read here is Gwyddion's ASCII matrix export (`# Width: 10.00 µm` header lines,
// then rows of numbers). Other AFM formats plug in by converting their map to HeightMap in read_height_map()
// once the mesh/afm readers exist (a few lines; see README.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tools/pstd/profiles.hpp"

namespace tribex::pstd {

/// Source samples (x strictly increasing), before oversampling.
struct RawProfile {
  std::vector<double> x, z;  // m
  std::string origin;
  double mean_spacing() const { return (x.back() - x.front()) / static_cast<double>(x.size() - 1); }
};

/// A text profile: optional `#` comment lines; either a header `x[UNIT],z[UNIT]` and two columns, or one z
/// per line (optional header `z[UNIT]`, default unit m) with the spacing `dx` (required then). Comma, tab or
/// blank separated. Errors are tools::BadInput naming file:line.
RawProfile read_profile_file(const std::string& path, std::optional<double> dx);

struct HeightMap {
  std::size_t nx = 0, ny = 0;  // columns (fast scan, x) and rows (y)
  double dx = 0.0, dy = 0.0;   // pixel sizes, m
  std::vector<double> z;       // row-major, z[row * nx + col], m
  std::string origin;
  RawProfile row(std::size_t r) const;     // along x: the scan direction
  RawProfile column(std::size_t c) const;  // along y: orthogonal to the scan direction
};

/// Reads a height map; today Gwyddion ASCII matrix text. Errors are tools::BadInput naming file:line.
HeightMap read_height_map(const std::string& path);

/// The whole source line, oversampled to spacing dx and closed periodically (the substrate).
Profile periodic_fine(const RawProfile& raw, double dx);
/// [start, start + length) of the source line, oversampled to dx; optionally levelled (least-squares line
/// removed from the source samples of the window first). Throws BadInput if the line is too short.
Profile window_fine(const RawProfile& raw, double start, double length, double dx, bool levelled);

}  // namespace tribex::pstd
