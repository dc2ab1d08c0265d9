// SPDX-License-Identifier: MIT
// The dimensions Exodus II gives the variables read_exodus reads (a fuzz finding, issue 54 item 11):
// libexodus fills our buffers, sized by one dimension (num_nodes), from a variable declared over
// another; a crafted file whose `coordx` spans num_elem would make the library write past them. The
// header walk (exodus_prescan.cpp) checks every such variable against this table, and
// check_netcdf4_exodus does for netCDF-4 files through the netCDF library.
#pragma once

#include <string>
#include <vector>

namespace tribex::mesh {

/// The dimension names, in order, Exodus II gives variable `name` (coordx: num_nodes; connect3:
/// num_el_in_blk3, num_nod_per_el3; ...); empty for a variable read_exodus does not read.
std::vector<std::string> exodus_dimensions_of(const std::string& name);

/// Whether the Exodus library reads global attribute `name` into a single value (version,
/// floating_point_word_size, int64_status, ...): the file must hold exactly one.
bool exodus_scalar_attribute(const std::string& name);

/// The same checks for a netCDF-4 (HDF5) Exodus file, which the classic header walk does not read:
/// through the netCDF library, before ex_open. Throws MeshError "PATH: ...".
void check_netcdf4_exodus(const std::string& path);

}  // namespace tribex::mesh
