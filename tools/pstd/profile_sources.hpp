// SPDX-License-Identifier: MIT
// Where PSTD profiles come from, before oversampling: profile files (CSV/text) and height maps (AFM). A height
// map gives the substrate as one row (the scan direction) and counterface segments as pieces of columns
// (orthogonal to the scan direction), as in the report. Positions and heights are SI.
//
// Height maps are read by mesh/afm (every format it knows: Nanoscope, .gsf, Gwyddion matrix, xyz text); this
// file only cuts lines out of them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mesh/afm/height_map.hpp"
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

/// Row iy of a height map: along x, the fast-scan direction; positions from 0, heights as stored (m).
RawProfile map_row(const mesh::afm::HeightMap& map, std::size_t iy);
/// Column ix of a height map: along y, orthogonal to the scan direction.
RawProfile map_column(const mesh::afm::HeightMap& map, std::size_t ix);

/// The most samples of one profile (source or model grid; issue 54, item 12): 1e8 doubles are 0.8 GB per
/// array, and a run's cost grows as the square of the count (steps x window). tools/pstd/README.md.
inline constexpr double kMaxProfileSamples = 1e8;
/// Throws BadInput naming `what` (e.g. "the substrate (10 um at --sampling 1e-30 m)"), the count and the
/// bound when count (a length over a spacing) is not finite or above kMaxProfileSamples; `fix` says what to change.
void check_sample_count(double count, const std::string& what, const std::string& fix);

/// The whole source line, oversampled to spacing dx and closed periodically (the substrate).
Profile periodic_fine(const RawProfile& raw, double dx);
/// [start, start + length) of the source line, oversampled to dx; optionally levelled (least-squares line
/// removed from the source samples of the window first). Throws BadInput if the line is too short.
Profile window_fine(const RawProfile& raw, double start, double length, double dx, bool levelled);

}  // namespace tribex::pstd
