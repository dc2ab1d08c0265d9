// SPDX-License-Identifier: MIT
// exodus_dimensions_of (exodus_shapes.hpp): the variable names and dimensions of the Exodus II format
// (Sandia's "Exodus II: a finite element data model"), for the variables read_exodus reads.
#include "mesh/exodus_shapes.hpp"

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

bool exodus_scalar_attribute(const std::string& name) {
  for (const char* scalar : {"api_version", "api version", "version", "floating_point_word_size", "floating point word size",
                             "file_size", "maximum_name_length", "int64_status", "last_written_time"})
    if (name == scalar) return true;
  return false;
}

}  // namespace tribex::mesh
