// SPDX-License-Identifier: MIT
// exodus_slices.hpp: ranges of an Exodus II file through the library's partial reads.
#include "mesh/exodus_slices.hpp"

#include <exodusII.h>

#include <algorithm>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw MeshError(path + ": " + what); }

std::string reason() {
  const std::string e = exodus::last_error();
  return e.empty() ? std::string() : " (" + e + ")";
}

}  // namespace

ExodusSlices::ExodusSlices(const std::string& path, bool walk_header)
    : path_(path), h_(exodus::open_checked(path, walk_header)) {
  try {
    node_sets_ = exodus::set_outline(h_.id, h_, false, path_);
    side_sets_ = exodus::set_outline(h_.id, h_, true, path_);
  } catch (...) {
    ex_close(h_.id);
    throw;
  }
}

ExodusSlices::~ExodusSlices() { close(); }

void ExodusSlices::close() {
  if (h_.id >= 0) ex_close(h_.id);
  h_.id = -1;
}

std::vector<int> ExodusSlices::connectivity(int first, int count) const {
  if (h_.id < 0) fail(path_, "read after the file was closed");
  std::vector<int> c(8 * static_cast<std::size_t>(count));
  // Each block holds a contiguous range of the elements: the slab's piece of each block is one hyperslab.
  for (std::size_t b = 0; b < h_.blocks.size(); ++b) {
    const Block& blk = h_.blocks[b];
    const int lo = std::max(first, blk.first_element), hi = std::min(first + count, blk.first_element + blk.element_count);
    if (lo >= hi) continue;
    if (ex_get_partial_conn(h_.id, EX_ELEM_BLOCK, h_.block_ids[b], lo - blk.first_element + 1, hi - lo,
                            c.data() + 8 * static_cast<std::size_t>(lo - first), nullptr, nullptr) < 0)
      fail(path_, "cannot read the connectivity of block '" + blk.name + "'" + reason());
  }
  for (int& n : c) {
    if (n < 1 || n > h_.nodes)
      fail(path_, "an element refers to node " + std::to_string(n) + ", outside 1.." + std::to_string(h_.nodes));
    n -= 1;
  }
  return c;
}

std::vector<double> ExodusSlices::coordinates(int first, int count) const {
  if (h_.id < 0) fail(path_, "read after the file was closed");
  std::vector<double> xyz(3 * static_cast<std::size_t>(count));
  if (count == 0) return xyz;
  std::vector<double> x(static_cast<std::size_t>(count)), y(x.size()), z(x.size());
  if (ex_get_partial_coord(h_.id, first + 1, count, x.data(), y.data(), z.data()) < 0)
    fail(path_, "cannot read the coordinates" + reason());
  const double s = h_.per_metre;  // read_exodus's arithmetic: the same doubles
  for (std::size_t i = 0; i < x.size(); ++i) {
    xyz[3 * i] = s == 1.0 ? x[i] : x[i] / s;
    xyz[3 * i + 1] = s == 1.0 ? y[i] : y[i] / s;
    xyz[3 * i + 2] = s == 1.0 ? z[i] : z[i] / s;
  }
  return xyz;
}

std::vector<int> ExodusSlices::node_set(std::size_t set, long long first, long long count) const {
  if (h_.id < 0) fail(path_, "read after the file was closed");
  std::vector<int> n(static_cast<std::size_t>(count));
  if (count == 0) return n;
  const std::string& name = node_sets_.names[set];
  if (ex_get_partial_node_set(h_.id, node_sets_.ids[set], first + 1, count, n.data()) < 0)
    fail(path_, "cannot read node set '" + name + "'" + reason());
  for (int& v : n) {
    if (v < 1 || v > h_.nodes)
      fail(path_, "node set '" + name + "' refers to node " + std::to_string(v) + ", outside 1.." + std::to_string(h_.nodes));
    v -= 1;
  }
  return n;
}

std::vector<Side> ExodusSlices::side_set(std::size_t set, long long first, long long count) const {
  if (h_.id < 0) fail(path_, "read after the file was closed");
  std::vector<Side> out;
  if (count == 0) return out;
  const std::string& name = side_sets_.names[set];
  std::vector<int> elements(static_cast<std::size_t>(count)), sides(elements.size());
  if (ex_get_partial_side_set(h_.id, side_sets_.ids[set], first + 1, count, elements.data(), sides.data()) < 0)
    fail(path_, "cannot read side set '" + name + "'" + reason());
  out.reserve(elements.size());
  for (std::size_t k = 0; k < elements.size(); ++k) {
    if (elements[k] < 1 || elements[k] > h_.elements || sides[k] < 1 || sides[k] > 6)
      fail(path_, "side set '" + name + "' has (element " + std::to_string(elements[k]) + ", side " +
                      std::to_string(sides[k]) + "), outside elements 1.." + std::to_string(h_.elements) +
                      " and HEX8 sides 1..6");
    out.push_back({elements[k] - 1, sides[k] - 1});
  }
  return out;
}

}  // namespace tribex::mesh
