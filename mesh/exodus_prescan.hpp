// SPDX-License-Identifier: MIT
// A bounds-checked walk of a netCDF classic / 64-bit offset / CDF5 header (the formats Exodus II files
// use, netCDF's "File Format Specification") before the Exodus library reads the file (issue 54,
// items 11 and 16): every size the header states is checked against the file's size before anything
// is allocated for it, so a cut file says "truncated", a netCDF file that is not Exodus says so, and
// a header that claims 2e9 elements is refused naming the size. netCDF-4 (HDF5) files are not walked:
// their counts are checked against the stated limits, their structure by check_netcdf4_exodus (exodus_shapes.hpp).
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace tribex::mesh {

/// What the walk found: the dimensions by name (a record dimension's length is the record count).
struct NetcdfHeader {
  std::map<std::string, std::uint64_t> dimensions;
  /// Where the last record ends when every record is complete (0: no records); the file's size. A mesh
  /// reader accepts a partly written last record; a join of rank files needs them whole.
  std::uint64_t records_end = 0, file_size = 0;
};

/// Walks `bytes` (the first bytes of a file of `file_size` bytes; the header must lie within them)
/// and checks every fixed-size variable's data against file_size. Throws MeshError "PATH: ..." on the
/// first problem (truncated, a size beyond the file, not Exodus II).
NetcdfHeader prescan_netcdf_classic(const std::string& path, const std::string& bytes, std::uint64_t file_size);

/// The header of the file at `path` (reads at most its first 16 MiB: the largest header walked).
NetcdfHeader prescan_exodus_file(const std::string& path);

}  // namespace tribex::mesh
