// SPDX-License-Identifier: MIT
// exodus_dimensions_of (exodus_shapes.hpp): the variable names and dimensions of the Exodus II format
// (Sandia's "Exodus II: a finite element data model"), for the variables read_exodus reads.
#include "mesh/exodus_shapes.hpp"

#include <netcdf.h>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

/// `name` = prefix followed by digits only: the digits in k.
bool numbered(const std::string& name, const std::string& prefix, std::string& k) {
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
  k = name.substr(prefix.size());
  return k.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

std::vector<std::string> exodus_dimensions_of(const std::string& name) {
  std::string k;
  if (name == "coordx" || name == "coordy" || name == "coordz" || name == "node_num_map") return {"num_nodes"};
  if (name == "coord") return {"num_dim", "num_nodes"};
  if (name == "elem_num_map") return {"num_elem"};
  if (name == "info_records") return {"num_info", "len_line"};
  if (name == "coor_names") return {"num_dim", "len_name"};
  if (name == "eb_names") return {"num_el_blk", "len_name"};
  if (name == "ns_names") return {"num_node_sets", "len_name"};
  if (name == "ss_names") return {"num_side_sets", "len_name"};
  if (name == "eb_status" || numbered(name, "eb_prop", k)) return {"num_el_blk"};
  if (name == "ns_status" || numbered(name, "ns_prop", k)) return {"num_node_sets"};
  if (name == "ss_status" || numbered(name, "ss_prop", k)) return {"num_side_sets"};
  if (numbered(name, "connect", k)) return {"num_el_in_blk" + k, "num_nod_per_el" + k};
  if (numbered(name, "node_ns", k)) return {"num_nod_ns" + k};
  if (numbered(name, "elem_ss", k) || numbered(name, "side_ss", k)) return {"num_side_ss" + k};
  return {};
}

void check_netcdf4_exodus(const std::string& path) {
  auto damaged = [&](const std::string& what) { throw MeshError(path + ": " + what + ": a damaged or crafted file"); };
  int ncid = -1;
  if (nc_open(path.c_str(), NC_NOWRITE, &ncid) != NC_NOERR)
    throw MeshError(path + ": the netCDF library cannot open this netCDF-4 file; is it truncated?");
  struct Closer {
    int id;
    ~Closer() { nc_close(id); }
  } closer{ncid};
  int natts = 0, nvars = 0;
  if (nc_inq_natts(ncid, &natts) != NC_NOERR || nc_inq_nvars(ncid, &nvars) != NC_NOERR) damaged("its header cannot be listed");
  for (int a = 0; a < natts; ++a) {
    char name[NC_MAX_NAME + 1] = {};
    std::size_t n = 0;
    if (nc_inq_attname(ncid, NC_GLOBAL, a, name) != NC_NOERR || nc_inq_attlen(ncid, NC_GLOBAL, name, &n) != NC_NOERR)
      damaged("a global attribute cannot be read");
    if (n != 1 && exodus_scalar_attribute(name))
      damaged(std::string("its global attribute '") + name + "' holds " + std::to_string(n) + " values where Exodus II has one");
  }
  int line_dim = -1;
  std::size_t line_length = 0;
  if (nc_inq_dimid(ncid, "len_line", &line_dim) == NC_NOERR && nc_inq_dimlen(ncid, line_dim, &line_length) == NC_NOERR &&
      line_length > 81)
    damaged("its dimension 'len_line' is " + std::to_string(line_length) + " where Exodus II has 81");
  for (int v = 0; v < nvars; ++v) {
    char name[NC_MAX_NAME + 1] = {};
    int ndims = 0;
    if (nc_inq_varname(ncid, v, name) != NC_NOERR || nc_inq_varndims(ncid, v, &ndims) != NC_NOERR || ndims < 0 ||
        ndims > NC_MAX_VAR_DIMS)
      damaged("variable " + std::to_string(v) + " cannot be read");
    const std::vector<std::string> expected = exodus_dimensions_of(name);
    if (expected.empty()) continue;
    std::vector<int> ids(static_cast<std::size_t>(ndims));
    if (ndims > 0 && nc_inq_vardimid(ncid, v, ids.data()) != NC_NOERR) damaged(std::string("variable '") + name + "' cannot be read");
    std::vector<std::string> found;
    std::string listed;
    for (int id : ids) {
      char dim[NC_MAX_NAME + 1] = {};
      if (nc_inq_dimname(ncid, id, dim) != NC_NOERR) damaged(std::string("variable '") + name + "' names no dimension");
      found.emplace_back(dim);
      listed += (listed.empty() ? "" : ", ") + found.back();
    }
    if (found != expected) {
      std::string wanted;
      for (const auto& d : expected) wanted += (wanted.empty() ? "" : ", ") + d;
      damaged(std::string("variable '") + name + "' has the dimensions (" + listed + ") where Exodus II has (" + wanted + ")");
    }
  }
}

bool exodus_scalar_attribute(const std::string& name) {
  for (const char* scalar : {"api_version", "api version", "version", "floating_point_word_size", "floating point word size",
                             "file_size", "maximum_name_length", "int64_status", "last_written_time"})
    if (name == scalar) return true;
  return false;
}

}  // namespace tribex::mesh
